// SPDX-License-Identifier: MIT
#include "ReferenceComparison.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "ReferenceFiles.h"
#include "core/Message.h"
#include "core/Node.h"
#include "simulation/VecId.h"

namespace stroma {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string listTimes(const std::vector<StateSnapshot>& snapshots) {
  std::string text;
  for (const StateSnapshot& s : snapshots)
    text += (text.empty() ? "" : ", ") + formatNumber(s.time);
  return text;
}

}  // namespace

ReferenceComparison::ReferenceComparison() {
  for (BaseData* output :
       {static_cast<BaseData*>(&d_maxError), static_cast<BaseData*>(&d_rmsError),
        static_cast<BaseData*>(&d_maxErrorAbsolute), static_cast<BaseData*>(&d_rmsErrorAbsolute),
        static_cast<BaseData*>(&d_meanError), static_cast<BaseData*>(&d_meanErrorAbsolute),
        static_cast<BaseData*>(&d_comparedTime), static_cast<BaseData*>(&d_worstIndex)})
    addOutput(output);
}

void ReferenceComparison::init() {
  m_ready = false;
  m_history.clear();
  m_pointIndex.clear();
  m_reportIndex.clear();
  m_location.clear();
  m_rest.clear();
  m_target.clear();
  m_targetDeflection.clear();
  m_snapshots.clear();
  m_deflectionOnly = false;
  publish({kNaN, kNaN, kNaN, -1});
  m_done.assign(d_times.value().size(), false);
  if (!l_state) l_state.set(node() ? node()->template get<State>() : nullptr);
  m_checked = checkParameters();
}

void ReferenceComparison::bwdInit() {
  // After every init (bottom-up): the state has its rest positions whatever the scene order.
  m_ready = false;
  if (!m_checked) return;

  // The rest shape the references are expressed on: the state's rest positions (its positions
  // when it keeps none).
  State* state = l_state.get();
  const State::VecCoord& rest = state->readCoord(VecId::restPosition()).size() == state->size()
                                    ? state->readCoord(VecId::restPosition())
                                    : state->readCoord(VecId::position());
  bool ok = false;
  if (d_analytic.value() != AnalyticReference::none)
    ok = prepareAnalytic(rest);
  else if (!d_referenceState.value().original.empty())
    ok = prepareStateFile(rest);
  else
    ok = prepareMarkers(rest);
  if (!ok) return;
  if (m_reportIndex.empty()) {
    msgError("no point to compare", "indices");
    return;
  }
  // The state size the comparison needs: a state that shrinks while running (cutting) is
  // reported instead of read out of range.
  m_requiredSize = 0;
  if (m_location.empty())
    for (unsigned i : m_pointIndex) m_requiredSize = std::max<std::size_t>(m_requiredSize, i + 1);
  for (const auto& e : m_location)
    for (int j = 0; j < e.count; ++j)
      m_requiredSize =
          std::max<std::size_t>(m_requiredSize, e.nodes[static_cast<std::size_t>(j)] + 1);
  m_sizeWarned = false;
  m_ready = true;
  setDirty();
}

bool ReferenceComparison::checkParameters() {
  bool ok = true;
  if (!l_state) {
    msgError("no 3-D mechanical state in the node: add a MechanicalObject or set state=\"@...\"",
             "state");
    ok = false;
  }
  if (!(d_referenceLength.value() > 0)) {
    msgError("referenceLength must be > 0 (the length errors are relative to), got " +
                 formatNumber(d_referenceLength.value()),
             "referenceLength");
    ok = false;
  }
  const int references = (d_analytic.value() != AnalyticReference::none) +
                         !d_referenceState.value().original.empty() +
                         !d_markers.value().original.empty();
  if (references != 1) {
    msgError(std::string(references ? "several references given" : "no reference given") +
                 ": set exactly one of analytic, referenceState, markers",
             references ? "analytic" : "referenceState");
    ok = false;
  }
  const std::vector<double>& times = d_times.value();
  for (std::size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1])) {
      msgError("times must increase (times[" + std::to_string(k) + "])", "times");
      ok = false;
      break;
    }
  return ok;
}

bool ReferenceComparison::prepareStateFile(const State::VecCoord& rest) {
  const std::string file = d_referenceState.value().path();
  std::ifstream in(file);
  if (!in) {
    msgError("cannot open the state file '" + file + "'", "referenceState");
    return false;
  }
  std::string error;
  if (!readStateFile(in, m_snapshots, error)) {
    msgError("state file '" + file + "': " + error, "referenceState");
    return false;
  }
  if (m_snapshots.empty()) {
    msgError("state file '" + file + "' has no snapshot", "referenceState");
    return false;
  }
  if (d_referenceTime.value() >= 0 &&
      !reference::findSnapshot(m_snapshots, d_referenceTime.value())) {
    msgError("state file '" + file + "' has no snapshot at time " +
                 formatNumber(d_referenceTime.value()) + " (it has " + listTimes(m_snapshots) + ")",
             "referenceTime");
    return false;
  }
  // Which state of the file: referencePath, else one with this state's path, else the only 3-D.
  std::string path = d_referencePath.value();
  if (path.empty())
    for (const StateRecord& r : m_snapshots.back().states)
      if (r.path == l_state->path()) path = r.path;
  d_referencePath.setValue(path);
  std::vector<Vec3d> last;
  for (const StateSnapshot& s : m_snapshots)
    if (!reference::statePositions(s, path, last, error)) {
      msgError("state file '" + file + "': " + error, "referenceState");
      return false;
    }
  const std::size_t count = last.size();
  std::vector<unsigned> points;
  if (!selectIndices(count, "reference's points", points)) return false;

  m_reportIndex = points;
  if (count == rest.size()) {  // the same points: compared by index
    m_pointIndex = points;
    for (unsigned i : points) m_rest.push_back(rest[i]);
    return true;
  }
  // Other points (another mesh): located at rest from the file's step-0 snapshot.
  if (m_snapshots.size() < 2 || m_snapshots.front().step != 0) {
    msgError("state file '" + file + "' has " + std::to_string(count) + " points and the state " +
                 std::to_string(rest.size()) +
                 ": to locate its points in this mesh it needs their rest positions, a snapshot "
                 "at step 0 (write it with --export-every)",
             "referenceState");
    return false;
  }
  std::vector<Vec3d> restOfFile;
  reference::statePositions(m_snapshots.front(), path, restOfFile, error);
  std::vector<Vec3d> located;
  for (unsigned i : points) located.push_back(restOfFile[i]);
  m_rest = located;
  m_pointIndex = points;  // indices into the file's points, for updateTargets
  return locateInMesh(rest, located, "referenceState");
}

bool ReferenceComparison::prepareMarkers(const State::VecCoord& rest) {
  const std::string file = d_markers.value().path();
  const auto columnsOf = [this](const std::vector<int>& c, const std::string& field,
                                reference::MarkerColumns& out) {
    if (c.size() != 3 || *std::min_element(c.begin(), c.end()) < 0) {
      msgError(
          "expected 3 column numbers >= 0 (x, y, z), got " + std::to_string(c.size()) + " numbers",
          field);
      return false;
    }
    out.position = {c[0], c[1], c[2]};
    out.scale = d_markerScale.value();
    return true;
  };
  std::vector<reference::MarkerColumns> columns(1);
  if (!columnsOf(d_markerColumns.value(), "markerColumns", columns[0])) return false;
  const bool locate = !d_restMarkerColumns.value().empty();
  if (locate) {
    columns.emplace_back();
    if (!columnsOf(d_restMarkerColumns.value(), "restMarkerColumns", columns[1])) return false;
  }
  std::vector<std::vector<Vec3d>> read;
  std::string error;
  if (!reference::readMarkerFile(file, columns, read, error)) {
    msgError(error, "markers");
    return false;
  }
  const std::size_t count = read[0].size();
  std::vector<unsigned> markers;
  if (!selectIndices(count, "marker file's markers", markers)) return false;
  for (unsigned i : markers) m_target.push_back(read[0][i]);
  m_reportIndex = markers;
  if (locate) {
    std::vector<Vec3d> located;
    for (unsigned i : markers) located.push_back(read[1][i]);
    m_rest = located;
    return locateInMesh(rest, located, "restMarkerColumns");
  }
  const std::vector<unsigned>& stateIndex = d_markerIndices.value();
  if (stateIndex.size() != count) {
    msgError("expected one state index per marker (" + std::to_string(count) + " in '" + file +
                 "'), got " + std::to_string(stateIndex.size()) +
                 " (or give restMarkerColumns to locate the markers in the mesh)",
             "markerIndices");
    return false;
  }
  for (unsigned i : markers) {
    if (stateIndex[i] >= rest.size()) {
      msgError("index " + std::to_string(stateIndex[i]) + " is out of range (the state has " +
                   std::to_string(rest.size()) + " points)",
               "markerIndices");
      return false;
    }
    m_pointIndex.push_back(stateIndex[i]);
    m_rest.push_back(rest[stateIndex[i]]);
  }
  return true;
}

bool ReferenceComparison::selectIndices(std::size_t count, const std::string& what,
                                        std::vector<unsigned>& selected) {
  selected = d_indices.value();
  for (unsigned i : selected)
    if (i >= count) {
      msgError("index " + std::to_string(i) + " is out of range (" + std::to_string(count) + " " +
                   what + ")",
               "indices");
      return false;
    }
  if (selected.empty())
    for (unsigned i = 0; i < count; ++i) selected.push_back(i);
  return true;
}

bool ReferenceComparison::locateInMesh(const State::VecCoord& rest,
                                       const std::vector<Vec3d>& points, const std::string& field) {
  Topology* topology =
      l_topology ? l_topology.get() : (node() ? node()->template getUp<Topology>() : nullptr);
  if (!topology || (topology->tetrahedra().empty() && topology->hexahedra().empty())) {
    msgError(
        "the reference points are not the state's points and no tetrahedra or hexahedra "
        "locate them: add a volume topology or set topology=\"@...\"",
        field);
    return false;
  }
  std::vector<Index> degenerate;
  m_location = barycentric::embedPoints(rest, topology->tetrahedra(), topology->hexahedra(), points,
                                        &degenerate);
  const double tolerance = 1e-6 * d_referenceLength.value();
  std::size_t outside = 0;
  double farthest = 0;
  for (const auto& p : m_location) {
    if (p.count == 0) {
      msgError("a reference point could not be located in the mesh (no element with volume)",
               field);
      return false;
    }
    if (p.distance > tolerance) ++outside;
    farthest = std::max(farthest, p.distance);
  }
  if (outside)
    msgWarning(std::to_string(outside) + " of " + std::to_string(points.size()) +
                   " reference points lie outside the mesh (up to " + formatNumber(farthest) +
                   "): their positions are extrapolated from the nearest element",
               field);
  return true;
}

bool ReferenceComparison::updateTargets(double time) {
  if (m_snapshots.empty()) return true;  // analytic and marker targets do not change
  const double wanted = d_referenceTime.value();
  const StateSnapshot* s = reference::findSnapshot(m_snapshots, wanted >= 0 ? wanted : time);
  if (!s) s = &m_snapshots.back();
  std::vector<Vec3d> positions;
  std::string error;
  reference::statePositions(*s, d_referencePath.value(), positions, error);
  m_target.clear();
  for (unsigned i : m_pointIndex) m_target.push_back(positions[i]);
  return true;
}

void ReferenceComparison::compareNow(double time) {
  updateTargets(time);
  const State::VecCoord& x = l_state->readCoord(VecId::position());
  if (x.size() < m_requiredSize) {
    if (!m_sizeWarned)
      msgWarning("the state now has " + std::to_string(x.size()) + " points and the reference " +
                     "needs " + std::to_string(m_requiredSize) +
                     ": no comparison (NaN) from time " + formatNumber(time),
                 "state");
    m_sizeWarned = true;
    const Comparison none{time, kNaN, kNaN, kNaN, -1};
    m_history.push_back(none);
    publish(none);
    return;
  }
  const Vec3d load = d_loadDirection.value().normalized();
  const std::size_t count = m_location.empty() ? m_pointIndex.size() : m_location.size();
  double sum = 0, sumSquares = 0, largest = -1;
  int worst = -1;
  for (std::size_t k = 0; k < count; ++k) {
    Vec3d p = Vec3d::Zero();
    if (m_location.empty()) {
      p = x[m_pointIndex[k]];
    } else {
      const barycentric::EmbeddedPoint& e = m_location[k];
      for (int j = 0; j < e.count; ++j)
        p += e.weights[static_cast<std::size_t>(j)] * x[e.nodes[static_cast<std::size_t>(j)]];
    }
    const double error = m_deflectionOnly
                             ? std::abs((p - m_rest[k]).dot(load) - m_targetDeflection[k])
                             : (p - m_target[k]).norm();
    sum += error;
    sumSquares += error * error;
    if (!std::isnan(largest) && (std::isnan(error) || error > largest)) {  // NaN is the worst
      largest = error;
      worst = static_cast<int>(k);
    }
  }
  const int named =
      worst >= 0 ? static_cast<int>(m_reportIndex[static_cast<std::size_t>(worst)]) : -1;
  const double n = static_cast<double>(count);
  const Comparison c{time, largest, std::sqrt(sumSquares / n), sum / n, named};
  m_history.push_back(c);
  publish(c);
}

void ReferenceComparison::publish(const Comparison& c) {
  const double L = d_referenceLength.value();
  d_maxErrorAbsolute.setValue(c.maxAbsolute);
  d_rmsErrorAbsolute.setValue(c.rmsAbsolute);
  d_maxError.setValue(L > 0 ? c.maxAbsolute / L : kNaN);
  d_rmsError.setValue(L > 0 ? c.rmsAbsolute / L : kNaN);
  d_meanErrorAbsolute.setValue(c.meanAbsolute);
  d_meanError.setValue(L > 0 ? c.meanAbsolute / L : kNaN);
  d_comparedTime.setValue(c.time);
  d_worstIndex.setValue(c.worst);
}

void ReferenceComparison::updatePosition(double dt) {
  // Called at the start of a step: the state is the one at the current time.
  if (!m_ready || !node()) return;
  const double time = node()->time();
  const std::vector<double>& times = d_times.value();
  for (std::size_t k = 0; k < times.size(); ++k)
    if (!m_done[k] && time >= times[k] - 0.5 * dt) {
      m_done[k] = true;
      compareNow(time);
    }
  setDirty();  // the solve changes the state: a later read of the outputs compares again
}

void ReferenceComparison::doUpdate() {
  if (!m_ready || !node()) return;
  const double time = node()->time();
  const std::vector<double>& times = d_times.value();
  if (times.empty()) {
    // The state may have changed since a comparison at this same time: that one is replaced.
    if (!m_history.empty() && m_history.back().time == time) m_history.pop_back();
    compareNow(time);
    return;
  }
  for (std::size_t k = 0; k < times.size(); ++k)
    if (!m_done[k] && time >= times[k] - 0.5 * node()->dt()) {
      m_done[k] = true;
      compareNow(time);
    }
}

std::vector<std::string> ReferenceComparison::runSummaryLines() const {
  d_maxError.value();  // compares now when due (the end of a run)
  if (!m_ready) return {"no comparison (see the errors above)"};
  std::vector<std::string> lines;
  const double L = d_referenceLength.value();
  // Without times, the comparison of the end only (an earlier read may have compared too).
  const std::size_t first =
      d_times.value().empty() && !m_history.empty() ? m_history.size() - 1 : 0;
  for (std::size_t k = first; k < m_history.size(); ++k) {
    const Comparison& c = m_history[k];
    lines.push_back("error at time " + formatNumber(c.time) + " s: max " +
                    formatNumber(c.maxAbsolute / L) + ", rms " + formatNumber(c.rmsAbsolute / L) +
                    ", mean " + formatNumber(c.meanAbsolute / L) +
                    " of referenceLength " + formatNumber(L) + " (max " +
                    formatNumber(c.maxAbsolute) + ", rms " + formatNumber(c.rmsAbsolute) +
                    ", worst point " + std::to_string(c.worst) + ")");
  }
  const std::vector<double>& times = d_times.value();
  for (std::size_t k = 0; k < times.size(); ++k)
    if (!m_done[k])
      lines.push_back("time " + formatNumber(times[k]) + " s not reached (the run ended at " +
                      formatNumber(node() ? node()->time() : 0.0) + " s)");
  return lines;
}

}  // namespace stroma
