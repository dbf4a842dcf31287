// SPDX-License-Identifier: MIT
#include "PrecomputedConstraintCorrection.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "CorrectionSupport.h"
#include "Precomputed/kernels/BasisCache.h"
#include "Precomputed/kernels/BasisSource.h"
#include "core/IndexChecks.h"
#include "core/Node.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Solvers.h"
#include "topology/Topology.h"

namespace stroma {

using precomputed::DeformationBasis;

namespace {

// Grows `m` to at least rows x cols (its top-left corner is what a step uses): no allocation
// once it has seen the largest problem.
void reserveBlock(Eigen::MatrixXd& m, Eigen::Index rows, Eigen::Index cols) {
  if (m.rows() < rows || m.cols() < cols)
    m.resize(std::max(rows, m.rows()), std::max(cols, m.cols()));
}

std::string hex(std::uint64_t key) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(key));
  return text;
}

}  // namespace

PrecomputedConstraintCorrection::PrecomputedConstraintCorrection() = default;
PrecomputedConstraintCorrection::~PrecomputedConstraintCorrection() = default;

const DeformationBasis* PrecomputedConstraintCorrection::compliance() const {
  return m_source ? m_source->deformationBasis() : m_compliance.get();
}

bool PrecomputedConstraintCorrection::findSolver() {
  // FreeMotionAnimationLoop looks for a correction in the solver's node or below it.
  for (Node* n = node(); n && !m_solver; n = n->parent()) m_solver = n->get<OdeSolver>();
  if (!m_solver) {
    msgError(
        "needs an ODE solver (EulerImplicitSolver, PrecomputedLinearModel...) in its node "
        "or above: the compliance is that of the solver's system");
    return false;
  }
  m_source = dynamic_cast<const precomputed::BasisSource*>(m_solver);
  return true;
}

void PrecomputedConstraintCorrection::bwdInit() {
  if (!node() || !isValid() || !findSolver()) return;
  // A solver that is its own compliance: nothing to precompute (its basis comes at its own
  // bwdInit, maybe after this one: it is read at each step).
  if (m_source) {
    if (!d_basisIndices.value().empty())
      msgWarning("unused: the compliance is the basis of " + m_solver->path() +
                     ", whose basisIndices say where constraint forces may act",
                 "basisIndices");
    return;
  }
  const double dt = node()->dt();
  MechanicalOperations mop(*m_solver->node(), m_timing, dt);
  const auto& states = mop.independentStates();
  m_state = states.size() == 1 ? dynamic_cast<MechanicalState<Vec3Types>*>(states[0]) : nullptr;
  if (!m_state) {
    msgError("works on one Vec3d state, and the system of " + m_solver->path() + " has " +
             std::to_string(states.size()) + " state(s)" +
             (states.size() == 1 ? " that is not Vec3d" : "") +
             ": use LinearSolverConstraintCorrection there");
    return;
  }
  ConstraintResponse response;
  if (!m_solver->constraintResponse(dt, response)) {
    msgError(m_solver->path() + " (" + m_solver->className() +
             ") cannot answer constraint forces: use EulerImplicitSolver, symplectic "
             "EulerExplicitSolver or StaticSolver");
    return;
  }
  if (!reportIndicesOutOfRange(*this, d_basisIndices.value(), m_state->size(), "basisIndices"))
    return;
  if (d_rotations.value() && !prepareRotations()) return;
  if (!precompute(mop, response)) return;
  // Step scratch, sized once.
  m_slotOfNode.assign(m_state->size(), -1);
  m_touched.reserve(m_state->size());
  m_u.resize(Eigen::Index(3 * m_state->size()));
  m_uRest.resize(m_compliance->columns().rows());
}

bool PrecomputedConstraintCorrection::prepareRotations() {
  // The one-rings come from the mesh of the state's node (or above).
  const Topology* topology = m_state->node() ? m_state->node()->getUp<Topology>() : nullptr;
  if (!topology || topology->allEdges().empty()) {
    msgError("the rotations need the mesh of " + m_state->path() +
                 " (a topology with edges or elements in its node or above); add one, or set "
                 "rotations=\"false\"",
             "rotations");
    return false;
  }
  m_rotations.build(m_state->size(), topology->allEdges());
  return true;
}

std::string PrecomputedConstraintCorrection::cachePath(std::uint64_t key) const {
  if (!d_fileCompliance.value().empty()) return d_fileCompliance.value();
  std::filesystem::path dir = d_fileDir.value();
  if (dir.empty()) {
    std::error_code ec;
    dir = std::filesystem::temp_directory_path(ec);
    dir = ec ? std::filesystem::path(".") : dir / "stroma-precomputed";
  }
  return (dir / (hex(key) + ".compliance")).string();
}

bool PrecomputedConstraintCorrection::precompute(MechanicalOperations& mop,
                                                 const ConstraintResponse& response) {
  const auto start = std::chrono::steady_clock::now();
  const auto& rest = m_state->readCoord(VecId::restPosition());
  const int n = int(rest.size());
  std::vector<char> fixed;
  mop.fixedGlobalRows(fixed);
  std::vector<int> fixedDofs, basisNodes;
  for (int dof = 0; dof < int(fixed.size()); ++dof)
    if (fixed[std::size_t(dof)]) fixedDofs.push_back(dof);
  if (d_basisIndices.value().empty())
    for (int i = 0; i < n; ++i) basisNodes.push_back(i);
  else
    basisNodes.assign(d_basisIndices.value().begin(), d_basisIndices.value().end());

  // A at rest. Forces first: corotational force fields take the rotations of their matrix from
  // their last force evaluation (during a step this leaves them at rest until the next step's
  // forces, which the solvers evaluate first).
  MechanicalParams atRest = response.matrix;
  atRest.x = VecId::restPosition();
  const VecId force = mop.allocDeriv();
  mop.computeForce(atRest, force);
  mop.freeVec(force);
  AssembledMatrix A;
  mop.assemble(atRest, A);
  const std::vector<double> factors{atRest.mFactor, atRest.bFactor, atRest.kFactor, atRest.dt};
  m_factors = {atRest.mFactor, atRest.bFactor, atRest.kFactor};
  const std::uint64_t key =
      precomputed::computeComplianceKey(A.matrix(), rest, fixedDofs, basisNodes, factors);
  d_complianceKey.setValue(hex(key));
  const std::string path = cachePath(key);

  std::string error;
  bool foreignFile = false;  // someone else's file under our name: left as it is
  if (std::filesystem::exists(path)) {
    foreignFile = !precomputed::isBasisCacheFile(path);
    if (foreignFile) {
      msgWarning("'" + path +
                     "' is not a Stroma compliance cache (SOFA's own format?): not read "
                     "and left as it is; the compliance is computed and not cached",
                 "fileCompliance");
    } else if (!d_recompute.value()) {
      auto loaded = precomputed::readBasisCache(path, key, error);
      if (loaded && (loaded->nodeCount() != n || int(loaded->rowNodes().size()) != n)) {
        error = "'" + path + "' holds " + std::to_string(loaded->rowNodes().size()) + " rows of " +
                std::to_string(loaded->nodeCount()) + " nodes, expected every one of " +
                std::to_string(n);
        loaded.reset();
      }
      if (loaded) {
        m_compliance = std::make_unique<DeformationBasis>(std::move(*loaded));
        d_loadedFromCache.setValue(true);
        d_precomputationTime.setValue(0.0);
        msgInfo("compliance loaded from '" + path + "'");
        return true;
      }
      msgWarning("cache not used: " + error + "; the compliance is recomputed and rewritten",
                 "fileCompliance");
    }
  }

  auto C = DeformationBasis::compute(A.matrix(), fixedDofs, basisNodes, error,
                                     DeformationBasis::FixedDofs::optional);
  if (!C) {
    msgError("the compliance of " + m_solver->path() + "'s system cannot be computed: " + error);
    return false;
  }
  m_compliance = std::make_unique<DeformationBasis>(std::move(*C));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  d_loadedFromCache.setValue(false);
  d_precomputationTime.setValue(seconds);
  std::string where = "not cached";
  if (!foreignFile) {
    if (precomputed::writeBasisCache(path, key, *m_compliance, error))
      where = "written to '" + path + "'";
    else
      msgWarning("the compliance could not be cached: " + error, "fileCompliance");
  }
  msgInfo("compliance computed in " + formatNumber(seconds) + " s (" + std::to_string(n) +
          " nodes, " + std::to_string(basisNodes.size()) + " columns' nodes), " + where);
  return true;
}

void PrecomputedConstraintCorrection::clearTouched() {
  for (int node : m_touched) m_slotOfNode[std::size_t(node)] = -1;
  m_touched.clear();
  m_touchedRows.clear();
  m_rows = 0;
}

bool PrecomputedConstraintCorrection::gatherRows(
    const DeformationBasis& C, const Eigen::SparseMatrix<double, Eigen::RowMajor>& H) {
  const auto m = H.rows();
  clearTouched();
  // The touched nodes (columns of C), in order of appearance.
  for (Eigen::Index r = 0; r < m; ++r) {
    bool acts = false;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(H, r); it; ++it) {
      const int node = int(it.col() / 3);
      if (m_slotOfNode[std::size_t(node)] >= 0) {
        acts = true;
        continue;
      }
      if (C.basisIndex(node) < 0) {
        // A fixed node (a zero row of C) does not move: nothing to say.
        const int row = C.rowIndex(node);
        const bool fixedNode = row >= 0 && C.columns().middleRows(3 * row, 3).isZero(0);
        if (!fixedNode && !m_warnedNode)
          msgWarning("a constraint acts on node " + std::to_string(node) +
                         ", which is not a "
                         "node of the compliance's columns: its rows are ignored there (and on any "
                         "other such node)",
                     m_source ? "" : "basisIndices");
        m_warnedNode = m_warnedNode || !fixedNode;
        continue;
      }
      m_slotOfNode[std::size_t(node)] = int(m_touched.size());
      m_touched.push_back(node);
      acts = true;
    }
    if (acts) m_touchedRows.push_back(int(r));
  }
  const auto t = Eigen::Index(m_touched.size());
  m_rows = m;
  if (t == 0) return false;

  // G = H R on the touched nodes (m x 3t): (H R)(r, 3s + j) = sum_c H(r, 3 node + c) R(c, j).
  reserveBlock(m_G, m, 3 * t);
  auto G = m_G.topLeftCorner(m, 3 * t);
  G.setZero();
  for (Eigen::Index r = 0; r < m; ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(H, r); it; ++it) {
      const auto node = std::size_t(it.col() / 3);
      const int slot = m_slotOfNode[node];
      if (slot < 0) continue;
      const int c = int(it.col() % 3);
      if (m_rotated)
        G.block<1, 3>(r, 3 * slot) += it.value() * m_rotations[node].row(c);
      else
        G(r, 3 * slot + c) += it.value();
    }
  // C_tt: the rows and columns of the touched nodes.
  reserveBlock(m_Ctt, 3 * t, 3 * t);
  for (Eigen::Index a = 0; a < t; ++a) {
    const int row = C.rowIndex(m_touched[std::size_t(a)]);
    for (Eigen::Index b = 0; b < t; ++b)
      m_Ctt.block<3, 3>(3 * a, 3 * b) =
          C.columns().block<3, 3>(3 * row, 3 * C.basisIndex(m_touched[std::size_t(b)]));
  }
  return true;
}

void PrecomputedConstraintCorrection::addCompliance(
    MechanicalOperations& mop, const ConstraintResponse& response,
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& H, Eigen::MatrixXd& W) {
  clearTouched();
  const DeformationBasis* C = compliance();
  if (!C) return;
  if (m_source) {
    // The solver's own basis: its nodes may have come after this bwdInit.
    if (m_slotOfNode.size() != std::size_t(C->nodeCount())) {
      m_slotOfNode.assign(std::size_t(C->nodeCount()), -1);
      m_touched.reserve(std::size_t(C->nodeCount()));
      m_u.resize(3 * C->nodeCount());
      m_uRest.resize(C->columns().rows());
    }
    m_rotated = false;
  } else {
    // The solver's factors (dt among them) must be those of the precomputation.
    const double factors[3] = {response.matrix.mFactor, response.matrix.bFactor,
                               response.matrix.kFactor};
    if (!std::equal(factors, factors + 3, m_factors.begin())) {
      msgWarning("the factors of " + m_solver->path() +
                 "'s system changed since the "
                 "precomputation (another dt?): the compliance is computed again");
      if (!precompute(mop, response)) return;
    }
    m_rotated = d_rotations.value();
    if (m_rotated)
      m_rotations.compute(m_state->readCoord(VecId::restPosition()),
                          m_state->readCoord(VecId::position()));
  }
  if (H.cols() != 3 * Eigen::Index(C->nodeCount())) {
    if (!m_warnedSize)
      msgWarning("the solver's system has " + std::to_string(H.cols()) +
                 " degrees of freedom, "
                 "the compliance " +
                 std::to_string(3 * C->nodeCount()) +
                 " (a topology "
                 "change?): this body takes no constraint force");
    m_warnedSize = true;
    return;
  }
  if (!gatherRows(*C, H)) return;

  // W += positionFactor G C_tt G^T.
  const auto m = H.rows(), t3 = 3 * Eigen::Index(m_touched.size());
  reserveBlock(m_T, t3, m);
  auto T = m_T.topLeftCorner(t3, m);
  T.noalias() = m_Ctt.topLeftCorner(t3, t3) * m_G.topLeftCorner(m, t3).transpose();
  W.noalias() += response.positionFactor * (m_G.topLeftCorner(m, t3) * T);
  const double regularization = d_regularizationTerm.value();
  if (regularization > 0)
    for (int r : m_touchedRows) W(r, r) += regularization;
}

void PrecomputedConstraintCorrection::applyCorrection(
    MechanicalOperations& mop, const ConstraintResponse& response,
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& H, const Eigen::VectorXd& lambda) {
  const DeformationBasis* C = compliance();
  if (!C || m_touched.empty() || H.rows() != m_rows || lambda.size() != m_rows) return;
  const auto t3 = 3 * Eigen::Index(m_touched.size());
  // f = G^T lambda: the forces on the touched nodes, in their rest frames.
  if (m_f.size() < t3) m_f.resize(t3);
  m_f.head(t3).noalias() = m_G.topLeftCorner(m_rows, t3).transpose() * lambda;
  // u_rest = C f over the rows of C, then u_i = R_i u_rest_i on the system's dofs.
  m_uRest.setZero();
  for (std::size_t a = 0; a < m_touched.size(); ++a) {
    const int column = 3 * C->basisIndex(m_touched[a]);
    m_uRest.noalias() += C->columns().middleCols<3>(column) * m_f.segment<3>(3 * Eigen::Index(a));
  }
  m_u.setZero();
  const auto& rows = C->rowNodes();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto node = std::size_t(rows[k]);
    const auto restPart = m_uRest.segment<3>(3 * Eigen::Index(k));
    if (m_rotated)
      m_u.segment<3>(3 * Eigen::Index(node)).noalias() = m_rotations[node] * restPart;
    else
      m_u.segment<3>(3 * Eigen::Index(node)) = restPart;
  }
  lagrangian::moveStates(mop, response, m_u);
}

}  // namespace stroma
