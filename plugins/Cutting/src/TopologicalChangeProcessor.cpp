// SPDX-License-Identifier: MIT
#include "TopologicalChangeProcessor.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_set>

#include "core/Node.h"

namespace stroma {

namespace {

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t end = i;
    while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end]))) ++end;
    if (end > i) words.push_back(line.substr(i, end - i));
    i = end;
  }
  return words;
}

template <class T>
bool parseNumber(std::string_view text, T& value) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size();
}

/// The element kind a container removes with SOFA's `REMOVE=` (removeItems of its modifier):
/// the kind its class is named after, else, for a container of any elements (MeshTopology,
/// grids), the highest kind it holds.
std::string removedKind(const Topology& topology) {
  const std::string& name = topology.className();
  static constexpr std::pair<std::string_view, const char*> kClassKinds[] = {
      {"Tetrahedron", "tetrahedra"},
      {"Hexahedron", "hexahedra"},
      {"Triangle", "triangles"},
      {"Quad", "quads"},
      {"Edge", "edges"},
      {"Point", "points"}};
  for (const auto& [prefix, kind] : kClassKinds)
    if (name.starts_with(prefix)) return kind;
  if (!topology.tetrahedra().empty()) return "tetrahedra";
  if (!topology.hexahedra().empty()) return "hexahedra";
  if (!topology.triangles().empty()) return "triangles";
  if (!topology.quads().empty()) return "quads";
  if (!topology.edges().empty()) return "edges";
  return "points";
}

}  // namespace

std::string TopologicalChangeProcessor::where(const Removal& removal, bool indexLine) const {
  if (removal.line == 0) return m_dataField;
  return d_filename.value().original + ":" + std::to_string(removal.line + (indexLine ? 1 : 0));
}

bool TopologicalChangeProcessor::readFile() {
  const FileName& file = d_filename.value();
  std::ifstream in(file.path());
  if (!in) {
    msgError("cannot open '" + file.path() + "'", "filename");
    return false;
  }
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(std::move(line));

  const std::string& name = file.original;
  auto fail = [&](std::size_t index, const std::string& what) {
    msgError(name + ":" + std::to_string(index + 1) + ": " + what, "filename");
    return false;
  };
  bool haveTime = false;
  double time = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::vector<std::string_view> words = splitWords(lines[k]);
    if (words.empty()) continue;
    const std::string_view command = words[0];
    // A block: "T= time".
    if (command == "T=") {
      double t = 0;
      if (words.size() < 2 || !parseNumber(words[1], t))
        return fail(k, "expected a time after 'T=', got '" + lines[k] + "'");
      if (haveTime && t < time)
        return fail(k, "times must increase: T= " + std::string(words[1]) +
                           " comes after T= " + std::to_string(time));
      time = t;
      haveTime = true;
      continue;
    }
    if (command == "ADD=" || command == "INCISE=")
      return fail(k, "'" + lines[k].substr(lines[k].find(command)) +
                         "': Stroma applies only REMOVE= (of tetrahedra and triangles) yet; adding "
                         "elements "
                         "and incisions are not supported");
    if (command != "REMOVE=")
      return fail(k, "unknown command '" + std::string(command) +
                         "': expected 'T= time' or a command (REMOVE=, ADD=, INCISE=)");
    if (!haveTime) return fail(k, "'REMOVE=' before the first 'T= time' line");
    long count = -1;
    if (words.size() < 2 || !parseNumber(words[1], count) || count < 0)
      return fail(k, "expected 'REMOVE= n' with n the number of elements (an integer >= 0), got '" +
                         lines[k] + "'");
    // The indices: the next line, n of them (SOFA reads missing ones as 0).
    if (k + 1 >= lines.size() && count > 0)
      return fail(k, "'REMOVE= " + std::to_string(count) +
                         "' needs its indices on the next line; the file ends");
    Removal removal{time, {}, static_cast<int>(k + 1)};
    const std::vector<std::string_view> indices =
        k + 1 < lines.size() ? splitWords(lines[k + 1]) : std::vector<std::string_view>{};
    for (std::string_view word : indices) {
      Index index = 0;
      if (!parseNumber(word, index))
        return fail(k + 1,
                    "expected element indices (integers >= 0), got '" + std::string(word) + "'");
      if (removal.indices.size() < static_cast<std::size_t>(count))
        removal.indices.push_back(index);
    }
    if (indices.size() != static_cast<std::size_t>(count))
      msgWarning(
          name + ":" + std::to_string(k + 2) + ": 'REMOVE= " + std::to_string(count) +
              "' is followed by " + std::to_string(indices.size()) + " indices: " +
              (indices.size() < static_cast<std::size_t>(count)
                   ? "the missing ones read as 0, as SOFA reads them"
                   : "the numbers past " + std::to_string(count) + " are ignored, as SOFA does"),
          "filename");
    removal.indices.resize(static_cast<std::size_t>(count), 0);
    m_removals.push_back(std::move(removal));
    ++k;  // the line of indices
  }
  return true;
}

void TopologicalChangeProcessor::init() {
  m_removals.clear();
  m_next = 0;
  m_removedCount = 0;
  m_topology = nullptr;
  m_onTriangles = false;
  m_dataField = "tetrahedraToRemove";
  if (d_useDataInputs.value()) {
    // Removals given as Data: one time, tetrahedra or triangles.
    for (const auto* other :
         {&d_pointsToRemove, &d_edgesToRemove, &d_quadsToRemove, &d_hexahedraToRemove})
      if (!other->value().empty()) {
        msgError("Stroma removes only tetrahedra and triangles at run time: " + other->name() +
                     " is not supported yet",
                 other->name());
        return;
      }
    if (!d_tetrahedraToRemove.value().empty() && !d_trianglesToRemove.value().empty()) {
      msgError(
          "give tetrahedraToRemove or trianglesToRemove, not both: a topology removes the "
          "elements of its own kind",
          "trianglesToRemove");
      return;
    }
    m_dataField = d_trianglesToRemove.value().empty() ? "tetrahedraToRemove" : "trianglesToRemove";
    const auto& indices = d_trianglesToRemove.value().empty() ? d_tetrahedraToRemove.value()
                                                              : d_trianglesToRemove.value();
    if (!indices.empty()) m_removals.push_back({d_timeToRemove.value(), indices, 0});
    return;
  }
  if (d_filename.value().original.empty()) {
    msgError(
        "no change file: set filename to a topological change file, or useDataInputs=\"true\" "
        "with timeToRemove and tetrahedraToRemove or trianglesToRemove",
        "filename");
    return;
  }
  readFile();
}

void TopologicalChangeProcessor::bwdInit() {
  // After every init, so that a topological mapping placed after this component has filled
  // the topology. The link, else the node's topology that has tetrahedra, else its first one.
  if (!isValid()) return;
  m_topology = l_topology.get();
  if (!m_topology && node())
    for (Topology* t : node()->getAll<Topology>())
      if (!m_topology || (m_topology->tetrahedra().empty() && !t->tetrahedra().empty()))
        m_topology = t;
  if (!m_topology) {
    msgError(
        "no topology to change: put a TetrahedronSetTopologyContainer in this node, or set "
        "topology=\"@path/to/container\"",
        "topology");
    return;
  }
  if (m_removals.empty()) return;
  // The kind of elements removed: the container's own (tetrahedra, or triangles of a surface).
  const std::string kind = removedKind(*m_topology);
  m_onTriangles = kind == "triangles" && m_topology->tetrahedra().empty();
  const std::string field = m_removals.front().line == 0 ? m_dataField : "filename";
  if (kind != "tetrahedra" && !m_onTriangles) {
    msgError(where(m_removals.front(), false) + ": 'REMOVE=' removes the " + kind + " of " +
                 m_topology->path() + " (" + m_topology->className() +
                 "): Stroma removes only tetrahedra and triangles at run time yet",
             field);
    return;
  }
  if (m_removals.front().line == 0 &&
      m_dataField != (m_onTriangles ? "trianglesToRemove" : "tetrahedraToRemove")) {
    msgError(m_topology->path() + " (" + m_topology->className() + ") removes its " + kind +
                 ": give " + (m_onTriangles ? "trianglesToRemove" : "tetrahedraToRemove"),
             m_dataField);
    return;
  }
  // Each removal against the number of elements left by the ones before it.
  const char* element = m_onTriangles ? "triangle " : "tetrahedron ";
  std::size_t count = elementCount();
  for (const Removal& removal : m_removals) {
    for (Index t : removal.indices)
      if (t >= count) {
        msgError(where(removal, true) + ": " + element + std::to_string(t) + " (time " +
                     std::to_string(removal.time) + ") does not exist: " + m_topology->path() +
                     " has " + std::to_string(count) + " " + kind + " then",
                 field);
        return;
      }
    const std::unordered_set<Index> distinct(removal.indices.begin(), removal.indices.end());
    count -= distinct.size();
  }
}

std::size_t TopologicalChangeProcessor::elementCount() const {
  return m_onTriangles ? m_topology->triangles().size() : m_topology->tetrahedra().size();
}

void TopologicalChangeProcessor::updatePosition(double dt) {
  if (!isValid() || !m_topology) return;
  const double t1 = node()->time() + dt;
  const double late = 1e-9 * dt;  // a time at t1 within round-off belongs to the next step
  for (; m_next < m_removals.size() && m_removals[m_next].time < t1 - late; ++m_next) {
    const Removal& removal = m_removals[m_next];
    std::string error;
    const std::size_t before = elementCount();
    const bool removed = m_onTriangles ? m_topology->removeTriangles(removal.indices, error)
                                       : m_topology->removeTetrahedra(removal.indices, error);
    if (!removed) {
      msgError(where(removal, true) + ": at time " + std::to_string(removal.time) +
                   ", cannot remove from " + m_topology->path() + ": " + error,
               removal.line == 0 ? m_dataField : "filename");
      return;
    }
    m_removedCount += before - elementCount();
  }
}

}  // namespace stroma
