// SPDX-License-Identifier: MIT
#include "topology/Topology.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

#include "core/Node.h"
#include "topology/MeshGeometry.h"

namespace stroma {

struct Topology::Cache {
  std::array<std::uint64_t, 6> versions{};  // of position and the five element lists
  std::uint64_t revision = 0;
  std::optional<std::size_t> nbPoints;
  std::optional<ElementEdges<3>> triangleEdges;
  std::optional<ElementEdges<4>> quadEdges;
  std::optional<ElementEdges<6>> tetrahedronEdges;
  std::optional<ElementEdges<12>> hexahedronEdges;
  std::optional<TetrahedronFaces> tetrahedronFaces;
  std::optional<std::vector<Triangle>> boundaryTriangles;
  std::optional<HexahedronFaces> hexahedronFaces;
  std::optional<std::vector<Quad>> boundaryQuads;
  std::optional<std::vector<Edge>> allEdges;
  std::optional<AdjacencyList> tetrahedraAroundVertex;
  std::optional<AdjacencyList> hexahedraAroundVertex;
  std::optional<AdjacencyList> edgesAroundVertex;

  /// Forgets everything derived from the elements.
  void clear() {
    const auto keepVersions = versions;
    const auto keepRevision = revision;
    *this = Cache{};
    versions = keepVersions;
    revision = keepRevision;
  }
};

Topology::Topology() : m_cache(std::make_unique<Cache>()) {}
Topology::~Topology() = default;

void Topology::refresh() const {
  // Reading the versions pulls linked values first, so a change upstream is seen here.
  const std::array<std::uint64_t, 6> now{d_position.version(),   d_edges.version(),
                                         d_triangles.version(),  d_quads.version(),
                                         d_tetrahedra.version(), d_hexahedra.version()};
  if (now == m_cache->versions) return;
  const bool elementsChanged =
      !std::equal(now.begin() + 1, now.end(), m_cache->versions.begin() + 1);
  const std::size_t oldPointCount = m_cache->nbPoints.value_or(0);
  m_cache->versions = now;
  if (elementsChanged) {
    ++m_cache->revision;
    m_cache->clear();
    return;
  }
  // Only the positions changed: adjacency holds unless the number of points did.
  m_cache->nbPoints.reset();
  std::size_t count = d_position.value().size();
  if (count == 0 || count != oldPointCount) {
    m_cache->tetrahedraAroundVertex.reset();
    m_cache->hexahedraAroundVertex.reset();
    m_cache->edgesAroundVertex.reset();
  }
}

std::uint64_t Topology::revision() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return m_cache->revision;
}

std::size_t Topology::nbPoints() const {
  std::lock_guard lock(m_mutex);
  refresh();
  if (!m_cache->nbPoints) {
    std::size_t count = d_position.value().size();
    if (count == 0) {
      auto scan = [&](const auto& elements) {
        for (const auto& element : elements)
          for (Index v : element) count = std::max<std::size_t>(count, std::size_t{v} + 1);
      };
      scan(d_edges.value());
      scan(d_triangles.value());
      scan(d_quads.value());
      scan(d_tetrahedra.value());
      scan(d_hexahedra.value());
    }
    m_cache->nbPoints = count;
  }
  return *m_cache->nbPoints;
}

namespace {

/// The cached value of `slot`, computed first when absent.
template <class T, class Compute>
const T& cached(std::optional<T>& slot, Compute&& compute) {
  if (!slot) slot = compute();
  return *slot;
}

}  // namespace

// Each accessor: lock, drop what is stale, compute on first use.
const ElementEdges<3>& Topology::triangleEdges() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->triangleEdges, [&] { return computeTriangleEdges(triangles()); });
}
const ElementEdges<4>& Topology::quadEdges() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->quadEdges, [&] { return computeQuadEdges(quads()); });
}
const ElementEdges<6>& Topology::tetrahedronEdges() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->tetrahedronEdges, [&] { return computeTetrahedronEdges(tetrahedra()); });
}
const ElementEdges<12>& Topology::hexahedronEdges() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->hexahedronEdges, [&] { return computeHexahedronEdges(hexahedra()); });
}
const TetrahedronFaces& Topology::tetrahedronFaces() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->tetrahedronFaces, [&] { return computeTetrahedronFaces(tetrahedra()); });
}
const std::vector<Triangle>& Topology::boundaryTriangles() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->boundaryTriangles, [&] { return computeBoundaryTriangles(tetrahedra()); });
}
const HexahedronFaces& Topology::hexahedronFaces() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->hexahedronFaces, [&] { return computeHexahedronFaces(hexahedra()); });
}
const std::vector<Quad>& Topology::boundaryQuads() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->boundaryQuads, [&] { return computeBoundaryQuads(hexahedra()); });
}
const std::vector<Edge>& Topology::allEdges() const {
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->allEdges, [&] {
    return computeAllEdges(edges(), triangles(), quads(), tetrahedra(), hexahedra());
  });
}

// The vertex lists need nbPoints(), which locks: compute it first, then lock.
const AdjacencyList& Topology::tetrahedraAroundVertex() const {
  const std::size_t n = nbPoints();
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->tetrahedraAroundVertex,
                [&] { return computeElementsAroundVertex<4>(tetrahedra(), n); });
}

const AdjacencyList& Topology::hexahedraAroundVertex() const {
  const std::size_t n = nbPoints();
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->hexahedraAroundVertex,
                [&] { return computeElementsAroundVertex<8>(hexahedra(), n); });
}

const AdjacencyList& Topology::edgesAroundVertex() const {
  const std::size_t n = nbPoints();
  const std::vector<Edge>& edges = allEdges();
  std::lock_guard lock(m_mutex);
  refresh();
  return cached(m_cache->edgesAroundVertex,
                [&] { return computeElementsAroundVertex<2>(edges, n); });
}

// --- Run-time changes ---------------------------------------------------------------------------

bool Topology::removeTetrahedra(std::span<const Index> indices, std::string& error) {
  {
    // Earlier changes made another way get their own revision first.
    std::lock_guard lock(m_mutex);
    refresh();
  }
  // This topology owns its lists from now on (a list that followed a loader stops following).
  auto own = [](auto& data) {
    data.value();
    std::string ignored;
    data.setParent(nullptr, ignored);
  };
  std::vector<Tetrahedron> tetrahedra = d_tetrahedra.value();
  std::vector<Triangle> triangles = d_triangles.value();
  std::vector<Edge> edges = d_edges.value();
  TopologyChange change;
  if (!removeTetrahedraFromLists(tetrahedra, triangles, edges, indices, change, error))
    return false;
  if (change.tetrahedra.empty()) return true;
  own(d_tetrahedra);
  d_tetrahedra.setValue(std::move(tetrahedra));
  if (!change.triangles.empty()) {
    own(d_triangles);
    d_triangles.setValue(std::move(triangles));
  }
  if (!change.edges.empty()) {
    own(d_edges);
    d_edges.setValue(std::move(edges));
  }
  {
    std::lock_guard lock(m_mutex);
    refresh();
    change.revision = m_cache->revision;
  }
  if (!change.freedPoints.empty() && !m_reportedFreedPoints) {
    m_reportedFreedPoints = true;
    msgWarning(std::to_string(change.freedPoints.size()) +
                   " points belong to no tetrahedron anymore (the first is point " +
                   std::to_string(change.freedPoints.front()) +
                   "): they are free, with no stiffness (and no mass from the elements); points "
                   "freed later are not reported",
               "tetrahedra");
  }
  if (m_changes.size() == kChangeLogCapacity) m_changes.erase(m_changes.begin());
  m_changes.push_back(std::move(change));
  return true;
}

bool Topology::removeTriangles(std::span<const Index> indices, std::string& error) {
  if (!d_tetrahedra.value().empty()) {
    error = "its triangles are the faces of its tetrahedra: remove tetrahedra instead";
    return false;
  }
  auto own = [](auto& data) {
    data.value();
    std::string ignored;
    data.setParent(nullptr, ignored);
  };
  std::vector<Triangle> triangles = d_triangles.value();
  std::vector<Edge> edges = d_edges.value();
  TopologyChange change;
  if (!removeTrianglesFromLists(triangles, edges, indices, change, error)) return false;
  if (change.triangles.empty()) return true;
  own(d_triangles);
  d_triangles.setValue(std::move(triangles));
  if (!change.edges.empty()) {
    own(d_edges);
    d_edges.setValue(std::move(edges));
  }
  if (!change.freedPoints.empty() && !m_reportedFreedPoints) {
    m_reportedFreedPoints = true;
    msgWarning(std::to_string(change.freedPoints.size()) +
                   " points belong to no triangle anymore (the first is point " +
                   std::to_string(change.freedPoints.front()) +
                   "): they are free, with no stiffness (and no mass from the elements); points "
                   "freed later are not reported",
               "triangles");
  }
  // Not logged: the components that follow the topology rebuild at their next use.
  return true;
}

std::optional<std::span<const TopologyChange>> Topology::changesSince(std::uint64_t since) const {
  const std::uint64_t now = revision();
  if (since > now) return std::nullopt;
  if (since == now) return std::span<const TopologyChange>();
  // The log must hold exactly the revisions since+1 .. now.
  const std::size_t count = static_cast<std::size_t>(now - since);
  if (count > m_changes.size()) return std::nullopt;
  const std::size_t first = m_changes.size() - count;
  for (std::size_t k = 0; k < count; ++k)
    if (m_changes[first + k].revision != since + 1 + k) return std::nullopt;
  return std::span<const TopologyChange>(m_changes.data() + first, count);
}

// --- Checks -----------------------------------------------------------------------------------

namespace {

constexpr std::size_t kListedElements = 10;

template <std::size_t N>
std::string describeElements(const std::vector<Index>& which,
                             const std::vector<std::array<Index, N>>& elements,
                             const char* singular) {
  std::string text;
  for (std::size_t i = 0; i < which.size() && i < kListedElements; ++i) {
    text += i ? ", " : "";
    text += std::string(singular) + " " + std::to_string(which[i]) + " (";
    for (std::size_t k = 0; k < N; ++k) {
      if (k) text += ' ';
      text += std::to_string(elements[which[i]][k]);
    }
    text += ")";
  }
  if (which.size() > kListedElements)
    text += " and " + std::to_string(which.size() - kListedElements) + " more";
  return text;
}

}  // namespace

bool Topology::checkElements() {
  bool ok = true;
  const std::vector<Vec3d>& points = d_position.value();
  if (!points.empty()) {
    auto checkRange = [&](const auto& data, const char* singular, const char* plural) {
      const auto& elements = data.value();
      const std::vector<Index> bad = findIndicesOutOfRange(std::span(elements), points.size());
      if (bad.empty()) return;
      msgError(std::to_string(bad.size()) + " " + (bad.size() == 1 ? singular : plural) +
                   " use point indices out of range (there are " + std::to_string(points.size()) +
                   " points, indices 0 to " + std::to_string(points.size() - 1) +
                   "): " + describeElements(bad, elements, singular),
               data.name());
      ok = false;
    };
    checkRange(d_edges, "edge", "edges");
    checkRange(d_triangles, "triangle", "triangles");
    checkRange(d_quads, "quad", "quads");
    checkRange(d_tetrahedra, "tetrahedron", "tetrahedra");
    checkRange(d_hexahedra, "hexahedron", "hexahedra");

    auto checkQuality = [&](const QualityReport& report, const auto& data, const char* singular,
                            const char* plural) {
      const auto& elements = data.value();
      if (!report.degenerate.empty()) {
        msgError(std::to_string(report.degenerate.size()) + " degenerate " +
                     (report.degenerate.size() == 1 ? singular : plural) +
                     " (volume about zero for the size): " +
                     describeElements(report.degenerate, elements, singular),
                 data.name());
        ok = false;
      }
      if (!report.inverted.empty())
        msgWarning(std::to_string(report.inverted.size()) + " inverted " +
                       (report.inverted.size() == 1 ? singular : plural) +
                       " (negative volume for SOFA's vertex order): " +
                       describeElements(report.inverted, elements, singular),
                   data.name());
    };
    checkQuality(checkTetrahedra(points, d_tetrahedra.value()), d_tetrahedra, "tetrahedron",
                 "tetrahedra");
    checkQuality(checkHexahedra(points, d_hexahedra.value()), d_hexahedra, "hexahedron",
                 "hexahedra");
  }
  return ok;
}

const Topology* findTetrahedralTopology(Base& owner, const Link<Topology>& link) {
  if (link) {
    if (link->tetrahedra().empty()) {
      owner.msgError("the topology " + link->path() + " has no tetrahedra", "topology");
      return nullptr;
    }
    return link.get();
  }
  for (const Node* node = owner.node(); node; node = node->parent()) {
    const Topology* found = nullptr;
    for (const Topology* topology : node->getAll<Topology>())
      if (!topology->tetrahedra().empty()) found = topology;
    if (found) return found;
  }
  owner.msgError(
      "needs a topology with tetrahedra (TetrahedronSetTopologyContainer, MeshTopology, or a "
      "grid through Hexa2TetraTopologicalMapping) in its node or above, or a 'topology' link",
      "topology");
  return nullptr;
}

}  // namespace stroma
