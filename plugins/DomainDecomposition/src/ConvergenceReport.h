// SPDX-License-Identifier: MIT
// The report of issue 6 (the shape of seed 000 figures 5.3 to 5.9): the error of the hybrid
// model to the single-domain static solution against the interface iteration count and the
// wall time, beside the same problem solved precomputed alone (one zone: exact after one
// iteration) and tensor-mass alone (one zone, dynamic relaxation, the seed's dynamic model).
#pragma once

#include <string>
#include <vector>

#include "DomainDecomposition/kernels/HybridDecomposition.h"

namespace stroma {

/// The problem and the decomposition to measure.
struct ConvergenceStudy {
  domaindecomposition::ElasticProblem problem;
  std::vector<int> zoneOfElement;
  std::vector<domaindecomposition::ZoneModel> models;
  domaindecomposition::Loads loads;
  domaindecomposition::DecompositionOptions options;
  int iterations = 200;
};

/// One run from u = 0: after each iteration k (1-based), the mean nodal error to the reference
/// divided by the mean edge length (the seed's "erreur normalisée") and the wall time so far.
struct ConvergenceCurve {
  std::string name;
  std::vector<double> iterations;
  std::vector<double> seconds;
  std::vector<double> error;
  std::size_t storedTensors = 0;  ///< 3x3 blocks of the precomputed zones
};

/// Runs the decomposition `zoneOfElement`/`models` of `study` and fills `curve`. False and
/// `error` when the setup fails.
bool measureConvergence(const ConvergenceStudy& study, const std::vector<int>& zoneOfElement,
                        const std::vector<domaindecomposition::ZoneModel>& models,
                        const Eigen::VectorXd& reference, double edgeLength,
                        ConvergenceCurve& curve, std::string& error);

/// Writes <prefix>_iterations.csv/.png and <prefix>_time.csv/.png (framework/report/Chart.h)
/// for the study's decomposition, precomputed alone and tensor-mass alone, and a one-line
/// summary per curve (time per iteration, iterations to 1e-3 and 1e-6 of the edge, storage).
/// A missing gnuplot leaves the PNGs out and says so in `summary`.
bool writeConvergenceReport(const ConvergenceStudy& study, const std::string& prefix,
                            std::string& summary, std::string& error);

}  // namespace stroma
