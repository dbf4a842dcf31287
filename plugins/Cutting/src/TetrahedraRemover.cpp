// SPDX-License-Identifier: MIT
#include "TetrahedraRemover.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <charconv>
#include <string_view>

#include "CuttingGeometry.h"
#include "core/Node.h"

namespace stroma {

namespace {

/// Parses "3 7 12, 40 41" into groups; false with `error` on a bad token.
bool parseGroups(const std::string& text, std::vector<std::vector<Index>>& groups,
                 std::string& error) {
  groups.clear();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return true;
  groups.emplace_back();
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ',') {
      groups.emplace_back();
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++i;
    } else {
      std::size_t end = i;
      while (end < text.size() &&
             std::string_view(" \t\r\n,").find(text[end]) == std::string_view::npos)
        ++end;
      // An index, or a range "a-b" as in SOFA's index lists.
      const std::string_view token(text.data() + i, end - i);
      const std::size_t dash = token.find('-', 1);
      auto number = [](std::string_view digits, Index& value) {
        const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        return ec == std::errc() && ptr == digits.data() + digits.size();
      };
      Index first = 0, last = 0;
      const bool ok = dash == std::string_view::npos ? number(token, first) && number(token, last)
                                                     : number(token.substr(0, dash), first) &&
                                                           number(token.substr(dash + 1), last) &&
                                                           first <= last && last - first < 10000000;
      if (!ok) {
        error =
            "expected tetrahedron indices (non-negative integers, or ranges 'a-b') in groups "
            "separated by commas, got '" +
            std::string(token) + "'";
        return false;
      }
      for (Index v = first;; ++v) {
        groups.back().push_back(v);
        if (v == last) break;
      }
      i = end;
    }
  }
  return true;
}

/// False when the tetrahedron uses a point past the positions (a topology the state does not
/// match, reported by the components that use both): it is not tested.
bool usesKnownPoints(const Tetrahedron& t, std::size_t pointCount) {
  return std::all_of(t.begin(), t.end(), [&](Index v) { return v < pointCount; });
}

}  // namespace

void TetrahedraRemover::init() {
  // Listed removals: one group per time, increasing times (the indices are checked against
  // the topology in bwdInit).
  std::string error;
  if (!parseGroups(d_tetrahedra.value(), m_groups, error)) {
    msgError(error, "tetrahedra");
    return;
  }
  const auto& times = d_times.value();
  if (m_groups.size() != times.size()) {
    msgError("has " + std::to_string(m_groups.size()) + " groups of tetrahedra for " +
                 std::to_string(times.size()) +
                 " times: give one group per time, groups separated by commas",
             "tetrahedra");
    return;
  }
  for (std::size_t k = 1; k < times.size(); ++k)
    if (times[k] < times[k - 1]) {
      msgError("times must increase: time " + std::to_string(k) + " (" + std::to_string(times[k]) +
                   ") is before time " + std::to_string(k - 1) + " (" +
                   std::to_string(times[k - 1]) + ")",
               "times");
      return;
    }
  // The tool: two end points, at the start and at the end.
  const auto& start = d_toolStart.value();
  const auto& end = d_toolEnd.value();
  if (!start.empty() && start.size() != 2)
    msgError("expected the 2 end points of the tool segment (6 numbers), got " +
                 std::to_string(start.size()) + " points",
             "toolStart");
  if (!end.empty() && (end.size() != 2 || start.empty()))
    msgError(start.empty() ? std::string("toolEnd needs toolStart")
                           : "expected the 2 end points of the tool segment (6 numbers), got " +
                                 std::to_string(end.size()) + " points",
             "toolEnd");
  for (const Vec6d& box : d_box.value())
    if (box[0] > box[3] || box[1] > box[4] || box[2] > box[5])
      msgError("a box is 'xmin ymin zmin xmax ymax zmax' with min <= max", "box");
  m_nextGroup = 0;
  m_removedCount = 0;
}

void TetrahedraRemover::bwdInit() {
  // After every init, so that a topological mapping placed after this component has filled
  // the topology. The link, else the node's topology that has tetrahedra (a grid may come
  // first), else the node's first topology.
  if (!isValid()) return;
  m_topology = l_topology.get();
  if (!m_topology && node())
    for (Topology* t : node()->getAll<Topology>())
      if (!m_topology || (m_topology->tetrahedra().empty() && !t->tetrahedra().empty()))
        m_topology = t;
  if (!m_topology) {
    msgError(
        "no topology to cut: put a TetrahedronSetTopologyContainer in this node, or set "
        "topology=\"@path/to/container\"",
        "topology");
    return;
  }
  m_state = node() ? node()->get<MechanicalState<Vec3Types>>() : nullptr;
  const auto& times = d_times.value();
  const std::size_t count = m_topology->tetrahedra().size();
  for (std::size_t k = 0; k < m_groups.size(); ++k)
    for (Index t : m_groups[k])
      if (t >= count) {
        msgError("tetrahedron " + std::to_string(t) + " (group " + std::to_string(k) + ", time " +
                     std::to_string(times[k]) + ") does not exist: " + m_topology->path() +
                     " has " + std::to_string(count) + " tetrahedra",
                 "tetrahedra");
        return;
      }
  if ((!d_box.value().empty() || !d_toolStart.value().empty()) && currentPoints().empty())
    msgError(
        "the box and the tool need positions: a Vec3d mechanical state in this node, or "
        "positions in " +
            m_topology->path(),
        d_box.value().empty() ? "toolStart" : "box");
}

const std::vector<Vec3d>& TetrahedraRemover::currentPoints() const {
  if (m_state && m_state->size() > 0) return m_state->readCoord(VecId::position());
  return m_topology->positions();
}

std::array<Vec3d, 2> TetrahedraRemover::toolAt(double t) const {
  const auto& start = d_toolStart.value();
  const auto& end = d_toolEnd.value().empty() ? start : d_toolEnd.value();
  const double t0 = d_startTime.value(), t1 = d_endTime.value();
  const double s = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  return {Vec3d((1 - s) * start[0] + s * end[0]), Vec3d((1 - s) * start[1] + s * end[1])};
}

void TetrahedraRemover::collectInBoxes(std::vector<Index>& out) const {
  const auto& points = currentPoints();
  const auto& tetrahedra = m_topology->tetrahedra();
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    if (!usesKnownPoints(tetrahedra[t], points.size())) continue;
    Vec3d centre = Vec3d::Zero();
    for (Index v : tetrahedra[t]) centre += 0.25 * points[v];
    for (const Vec6d& box : d_box.value())
      if (centre.x() >= box[0] && centre.y() >= box[1] && centre.z() >= box[2] &&
          centre.x() <= box[3] && centre.y() <= box[4] && centre.z() <= box[5]) {
        out.push_back(static_cast<Index>(t));
        break;
      }
  }
}

void TetrahedraRemover::collectCrossedByTool(double from, double to,
                                             std::vector<Index>& out) const {
  // The surface the segment sweeps from `from` to `to`: the quad (a0, b0, b1, a1), as two
  // triangles (the segment itself when the tool does not move).
  const auto [a0, b0] = toolAt(from);
  const auto [a1, b1] = toolAt(to);
  Eigen::AlignedBox3d sweep;
  for (const Vec3d& p : {a0, b0, a1, b1}) sweep.extend(p);
  const auto& points = currentPoints();
  const auto& tetrahedra = m_topology->tetrahedra();
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    if (!usesKnownPoints(tetrahedra[t], points.size())) continue;
    cutting::TetrahedronPoints x;
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 4; ++k) box.extend(x[k] = points[tetrahedra[t][k]]);
    if (!box.intersects(sweep)) continue;
    if (cutting::triangleMeetsTetrahedron(a0, b0, b1, x) ||
        cutting::triangleMeetsTetrahedron(a0, b1, a1, x))
      out.push_back(static_cast<Index>(t));
  }
}

void TetrahedraRemover::updatePosition(double dt) {
  if (!isValid() || !m_topology) return;
  const double t0 = node()->time(), t1 = t0 + dt;
  const double late = 1e-9 * dt;  // a time at t1 within round-off belongs to the next step

  // Listed removals, each as its own change (the indices of a group are in the numbering of
  // its time).
  const auto& times = d_times.value();
  for (; m_nextGroup < times.size() && times[m_nextGroup] < t1 - late; ++m_nextGroup) {
    const auto& group = m_groups[m_nextGroup];
    std::string error;
    const std::size_t before = m_topology->tetrahedra().size();
    if (!m_topology->removeTetrahedra(group, error)) {
      msgError("at time " + std::to_string(times[m_nextGroup]) + " (group " +
                   std::to_string(m_nextGroup) + "), cannot remove from " + m_topology->path() +
                   ": " + error,
               "tetrahedra");
      return;
    }
    m_removedCount += before - m_topology->tetrahedra().size();
  }

  // Box and tool, while active.
  const double start = d_startTime.value(), end = d_endTime.value();
  const bool bounded = end > start;
  if (t1 - late <= start || (bounded && t0 > end)) return;
  std::vector<Index> remove;
  if (!d_box.value().empty()) collectInBoxes(remove);
  if (d_toolStart.value().size() == 2)
    collectCrossedByTool(std::max(t0, start), bounded ? std::min(t1, end) : t1, remove);
  if (remove.empty()) return;
  std::string error;
  const std::size_t before = m_topology->tetrahedra().size();
  if (!m_topology->removeTetrahedra(remove, error)) {
    msgError("cannot remove from " + m_topology->path() + ": " + error, "tetrahedra");
    return;
  }
  m_removedCount += before - m_topology->tetrahedra().size();
  if (d_printLog.value())
    msgInfo("removed " + std::to_string(before - m_topology->tetrahedra().size()) +
            " tetrahedra at t = " + std::to_string(t0) + " (" + std::to_string(m_removedCount) +
            " so far)");
}

}  // namespace stroma
