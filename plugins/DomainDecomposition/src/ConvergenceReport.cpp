// SPDX-License-Identifier: MIT
#include "ConvergenceReport.h"

#include <chrono>

#include "DomainDecomposition/kernels/SingleDomainReference.h"
#include "core/Message.h"
#include "report/Chart.h"

namespace stroma {

using namespace domaindecomposition;

bool measureConvergence(const ConvergenceStudy& study, const std::vector<int>& zoneOfElement,
                        const std::vector<ZoneModel>& models, const Eigen::VectorXd& reference,
                        double edgeLength, ConvergenceCurve& curve, std::string& error) {
  HybridDecomposition hybrid;
  if (!hybrid.setup(study.problem, zoneOfElement, models, study.loads, study.options, error))
    return false;
  curve.storedTensors = hybrid.storedTensors();
  double seconds = 0;
  for (int k = 1; k <= study.iterations; ++k) {
    const auto start = std::chrono::steady_clock::now();
    hybrid.iterate();
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    curve.iterations.push_back(k);
    curve.seconds.push_back(seconds);
    curve.error.push_back(compareDisplacements(hybrid.displacement(), reference).mean / edgeLength);
  }
  return true;
}

namespace {

/// The first iteration count whose error is below `level`, as text ("never" otherwise).
std::string iterationsTo(const ConvergenceCurve& curve, double level) {
  for (std::size_t k = 0; k < curve.error.size(); ++k)
    if (curve.error[k] < level) return std::to_string(k + 1);
  return "> " + std::to_string(curve.error.size());
}

}  // namespace

bool writeConvergenceReport(const ConvergenceStudy& study, const std::string& prefix,
                            std::string& summary, std::string& error) {
  Eigen::VectorXd reference;
  if (!solveSingleDomain(study.problem, study.loads, reference, error)) return false;
  const double edge = computeMeanEdgeLength(study.problem.points, study.problem.tetrahedra);
  int zoneCount = static_cast<int>(study.models.size());

  std::vector<ConvergenceCurve> curves(3);
  curves[0].name = "hybrid, " + std::to_string(zoneCount) + " zones";
  curves[1].name = "precomputed alone";
  curves[2].name = "tensor-mass alone (relaxation)";
  const std::vector<int> oneZone(study.problem.tetrahedra.size(), 0);
  ConvergenceStudy single = study;
  single.options.tensorMassSolve = TensorMassSolve::relaxation;
  if (!measureConvergence(study, study.zoneOfElement, study.models, reference, edge, curves[0],
                          error) ||
      !measureConvergence(single, oneZone, {ZoneModel::precomputed}, reference, edge, curves[1],
                          error) ||
      !measureConvergence(single, oneZone, {ZoneModel::tensorMass}, reference, edge, curves[2],
                          error))
    return false;

  std::vector<report::ChartSeries> byIteration, byTime;
  for (const ConvergenceCurve& curve : curves) {
    byIteration.push_back({curve.name, curve.iterations, curve.error});
    byTime.push_back({curve.name, curve.seconds, curve.error});
    const double perIteration = curve.seconds.back() / static_cast<double>(curve.seconds.size());
    summary += curve.name + ": " + formatNumber(perIteration * 1e6) + " us per iteration (" +
               formatNumber(1.0 / perIteration) + " Hz), error/edge " +
               formatNumber(curve.error.back()) + " after " + std::to_string(curve.error.size()) +
               " iterations, below 1e-3 after " + iterationsTo(curve, 1e-3) +
               ", below 1e-6 after " + iterationsTo(curve, 1e-6) + ", stored 3x3 blocks " +
               std::to_string(curve.storedTensors) + "\n";
  }
  const report::ChartAxes iterationAxes{"Error to the single-domain solution",
                                        "interface iterations",
                                        "mean nodal error / mean edge length", false, true};
  report::ChartAxes timeAxes = iterationAxes;
  timeAxes.xLabel = "wall time (s)";
  timeAxes.logX = true;
  for (const auto& [path, problem] :
       {std::pair{prefix + "_iterations.csv",
                  report::writeChartCsv(prefix + "_iterations.csv", iterationAxes, byIteration)},
        std::pair{prefix + "_time.csv",
                  report::writeChartCsv(prefix + "_time.csv", timeAxes, byTime)}})
    if (!problem.empty()) {
      error = path + ": " + problem;
      return false;
    }
  std::string png = report::writeChartPng(prefix + "_iterations.png", iterationAxes, byIteration);
  if (png.empty()) png = report::writeChartPng(prefix + "_time.png", timeAxes, byTime);
  if (!png.empty()) summary += "PNG not written: " + png + "\n";
  return true;
}

}  // namespace stroma
