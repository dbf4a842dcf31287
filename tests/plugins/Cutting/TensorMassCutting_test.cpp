// SPDX-License-Identifier: MIT
// The tensor-mass force fields follow removed tetrahedra incrementally (TensorMassRemoval.h):
// after the removals every stored tensor, vector and scalar equals the one rebuilt from scratch
// on the remaining tetrahedra (to round-off, whatever order and orientation the primitives are
// stored in), and a thousand removals do not grow the memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../../../plugins/TensorMass/src/TetrahedralStVKTensorMassForceField.h"
#include "../../../plugins/TensorMass/src/TetrahedralTensorMassForceField.h"
#include "../../../plugins/Topology/src/TetrahedronSetTopologyModifier.h"
#include "plugins/Spring/MechanicsTestSupport.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// A block of n x 2 x 2 cubes in six tetrahedra each, with the force field FIELD.
std::string block(const std::string& field, int n, const std::string& tetrahedra = "") {
  const std::string topology =
      tetrahedra.empty()
          ? R"(<TetrahedronSetTopologyContainer name="topology"/>
    <TetrahedronSetTopologyModifier name="modifier"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topology"/>)"
          : R"(<TetrahedronSetTopologyContainer name="topology" position="@grid.position" tetrahedra=")" +
                tetrahedra + R"("/>)";
  return R"(
<Node name="root" dt="0.01" gravity="0 0 0">
  <RegularGridTopology name="grid" min="0 0 0" max=")" +
         std::to_string(0.1 * n) + R"( 0.2 0.2" n=")" + std::to_string(n + 1) + R"( 3 3"/>
  <MechanicalObject name="dofs" template="Vec3" position="@grid.position"/>
  )" + topology +
         R"(
  <)" + field +
         (field.find(' ') == std::string::npos
              ? std::string(R"( name="field" youngModulus="5000" poissonRatio="0.35")")
              : std::string()) +
         R"(/>
</Node>)";
}

template <class T>
T* component(SceneHolder& s, const std::string& path, const std::string& className) {
  Base* b = s.get<Base>(path);
  EXPECT_TRUE(b && b->className() == className) << path;
  return b && b->className() == className ? static_cast<T*>(b) : nullptr;
}

/// Removes `batches` from the loaded block through its modifier, one change each, making the
/// force field follow after each (a force computation), then loads the remaining mesh afresh.
void cutAndRebuild(SceneHolder& cut, SceneHolder& rebuilt, const std::string& field,
                   const std::vector<std::vector<Index>>& batches) {
  ASSERT_TRUE(cut.load(block(field, 4)));
  auto* modifier =
      component<TetrahedronSetTopologyModifier>(cut, "@modifier", "TetrahedronSetTopologyModifier");
  ASSERT_TRUE(modifier);
  ForceFieldChecker checker(cut.scene(), cut.root());
  for (const auto& batch : batches) {
    ASSERT_TRUE(modifier->removeTetrahedra(batch));
    checker.force();
  }
  ASSERT_TRUE(rebuilt.load(block(field, 4, cut.text("@topology.tetrahedra"))));
}

const std::vector<std::vector<Index>> kBatches{{0, 5, 17, 40, 41}, {3, 60, 61, 62}, {7}, {20, 21}};

double scaleOf(const std::vector<Matrix3d>& tensors) {
  double s = 0;
  for (const Matrix3d& m : tensors) s = std::max(s, m.cwiseAbs().maxCoeff());
  return s;
}

std::uint64_t edgeKey(Index a, Index b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

TEST(TensorMassCutting, LinearTensorsEqualARebuild) {
  SceneHolder cut, rebuilt;
  cutAndRebuild(cut, rebuilt, "TetrahedralTensorMassForceField", kBatches);
  const auto& a =
      component<TetrahedralTensorMassForceField>(cut, "@field", "TetrahedralTensorMassForceField")
          ->tensors();
  const auto& b = component<TetrahedralTensorMassForceField>(rebuilt, "@field",
                                                             "TetrahedralTensorMassForceField")
                      ->tensors();
  const double tolerance = 1e-12 * scaleOf(b.vertexTensors);
  ASSERT_EQ(a.vertexTensors.size(), b.vertexTensors.size());
  for (std::size_t p = 0; p < a.vertexTensors.size(); ++p)
    EXPECT_LT((a.vertexTensors[p] - b.vertexTensors[p]).cwiseAbs().maxCoeff(), tolerance) << p;
  // K^pj by (min, max) vertex: K^jp = (K^pj)^T.
  auto byEdge = [](const tensormass::VertexEdgeTensors& t) {
    std::map<std::uint64_t, Matrix3d> out;
    for (std::size_t e = 0; e < t.edges.size(); ++e)
      out[edgeKey(t.edges[e][0], t.edges[e][1])] =
          t.edges[e][0] < t.edges[e][1] ? t.edgeTensors[e] : Matrix3d(t.edgeTensors[e].transpose());
    return out;
  };
  const auto ea = byEdge(a), eb = byEdge(b);
  ASSERT_EQ(ea.size(), eb.size());
  for (const auto& [key, K] : eb) {
    ASSERT_TRUE(ea.contains(key));
    EXPECT_LT((ea.at(key) - K).cwiseAbs().maxCoeff(), tolerance);
  }
}

/// The St Venant-Kirchhoff terms keyed by their sorted vertices, in a canonical orientation.
struct CanonicalStVK {
  std::vector<tensormass::StVKTensorMass::VertexTerms> vertices;
  std::map<std::uint64_t, tensormass::StVKTensorMass::EdgeTerms> edges;
  /// Per triangle (sorted vertices), per vertex in that order: (c, e_i "g_ii g_jk",
  /// e "the product of the two g around vertex i").
  std::map<std::array<Index, 3>, std::array<std::tuple<Vector3d, double, double>, 3>> triangles;
  /// Per tetrahedron (sorted vertices): the scalar of each pairing {{a, x}, {..}}, x = b, c, d.
  std::map<std::array<Index, 4>, std::array<double, 3>> tetrahedra;

  explicit CanonicalStVK(const tensormass::StVKTensorMass& m) : vertices(m.vertices) {
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
      auto t = m.edgeTerms[e];
      if (m.edges[e][0] > m.edges[e][1]) {  // swap a and b
        t.K.transposeInPlace();
        std::swap(t.c[0], t.c[3]);
        std::swap(t.c[1], t.c[2]);
        std::swap(t.d[0], t.d[1]);
      }
      edges[edgeKey(m.edges[e][0], m.edges[e][1])] = t;
    }
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      const Triangle& v = m.triangles[f];
      const auto& t = m.triangleTerms[f];
      // Vertex i of (a, b, c): c[i], e[i] (g_ii times the g of the other two), e[3 + i].
      std::array<std::pair<Index, std::tuple<Vector3d, double, double>>, 3> perVertex;
      for (int i = 0; i < 3; ++i) perVertex[i] = {v[i], {t.c[i], t.e[i], t.e[3 + i]}};
      std::sort(perVertex.begin(), perVertex.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      triangles[{perVertex[0].first, perVertex[1].first, perVertex[2].first}] = {
          perVertex[0].second, perVertex[1].second, perVertex[2].second};
    }
    for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
      const Tetrahedron& v = m.tetrahedra[t];
      // Pairings of (v0 v1 v2 v3): t1 {01}{23}, t2 {02}{13}, t3 {03}{12}: keyed by the partner
      // of the smallest vertex.
      Tetrahedron sorted = v;
      std::sort(sorted.begin(), sorted.end());
      std::array<double, 3> terms{};
      const std::array<std::array<int, 2>, 3> pairs{{{0, 1}, {0, 2}, {0, 3}}};
      for (int k = 0; k < 3; ++k) {
        // The pairing k puts v0 with v[pairs[k][1]]; the other pair is the rest.
        const Index with0 = v[pairs[k][1]];
        Index partner;  // the partner of sorted[0] in this pairing
        if (sorted[0] == v[0]) {
          partner = with0;
        } else if (sorted[0] == with0) {
          partner = v[0];
        } else {
          // sorted[0] is in the other pair: its partner is the remaining vertex.
          partner = kInvalidIndex;
          for (int i = 1; i < 4; ++i)
            if (v[i] != with0 && v[i] != sorted[0]) partner = v[i];
        }
        const int slot =
            static_cast<int>(std::find(sorted.begin(), sorted.end(), partner) - sorted.begin()) - 1;
        terms[slot] = m.tetrahedronTerms[t][k];
      }
      tetrahedra[sorted] = terms;
    }
  }
};

TEST(TensorMassCutting, StVKTermsEqualARebuild) {
  SceneHolder cut, rebuilt;
  cutAndRebuild(cut, rebuilt, "TetrahedralStVKTensorMassForceField", kBatches);
  const auto* fa = component<TetrahedralStVKTensorMassForceField>(
      cut, "@field", "TetrahedralStVKTensorMassForceField");
  const auto* fb = component<TetrahedralStVKTensorMassForceField>(
      rebuilt, "@field", "TetrahedralStVKTensorMassForceField");
  const CanonicalStVK a(fa->model()), b(fb->model());
  double scale = 0;  // of each kind of term, for relative tolerances
  for (const auto& v : b.vertices) scale = std::max(scale, v.K.cwiseAbs().maxCoeff());
  const double tolK = 1e-12 * scale;
  double scaleC = 0, scaleD = 0;
  for (const auto& v : b.vertices) {
    scaleC = std::max(scaleC, v.c.cwiseAbs().maxCoeff());
    scaleD = std::max(scaleD, std::abs(v.d));
  }
  const double tolC = 1e-12 * scaleC, tolD = 1e-12 * scaleD;

  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t p = 0; p < a.vertices.size(); ++p) {
    EXPECT_LT((a.vertices[p].K - b.vertices[p].K).cwiseAbs().maxCoeff(), tolK) << p;
    EXPECT_LT((a.vertices[p].c - b.vertices[p].c).cwiseAbs().maxCoeff(), tolC) << p;
    EXPECT_NEAR(a.vertices[p].d, b.vertices[p].d, tolD) << p;
  }
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (const auto& [key, t] : b.edges) {
    ASSERT_TRUE(a.edges.contains(key));
    const auto& u = a.edges.at(key);
    EXPECT_LT((u.K - t.K).cwiseAbs().maxCoeff(), tolK);
    for (int i = 0; i < 4; ++i) {
      EXPECT_LT((u.c[i] - t.c[i]).cwiseAbs().maxCoeff(), tolC);
      EXPECT_NEAR(u.d[i], t.d[i], tolD);
    }
  }
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (const auto& [key, t] : b.triangles) {
    ASSERT_TRUE(a.triangles.contains(key));
    for (int i = 0; i < 3; ++i) {
      const auto& [c1, e1, f1] = a.triangles.at(key)[i];
      const auto& [c2, e2, f2] = t[i];
      EXPECT_LT((c1 - c2).cwiseAbs().maxCoeff(), tolC);
      EXPECT_NEAR(e1, e2, tolD);
      EXPECT_NEAR(f1, f2, tolD);
    }
  }
  ASSERT_EQ(a.tetrahedra.size(), b.tetrahedra.size());
  for (const auto& [key, t] : b.tetrahedra) {
    ASSERT_TRUE(a.tetrahedra.contains(key));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.tetrahedra.at(key)[i], t[i], tolD);
  }
  // The physics agrees too: forces and tangent at a deformed state.
  std::string text;
  const auto x = numbers(cut.text("@dofs.position"));
  for (std::size_t i = 0; i < x.size(); ++i)
    text += std::to_string(x[i] * (1 + 0.05 * std::sin(double(i)))) + " ";
  cut.set("@dofs.position", text);
  rebuilt.set("@dofs.position", text);
  ForceFieldChecker ca(cut.scene(), cut.root()), cb(rebuilt.scene(), rebuilt.root());
  const Eigen::VectorXd f1 = ca.force(), f2 = cb.force();
  EXPECT_LT((f1 - f2).cwiseAbs().maxCoeff(), 1e-11 * f2.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd K1 = ca.assembled(0, 0, 1), K2 = cb.assembled(0, 0, 1);
  EXPECT_LT((K1 - K2).cwiseAbs().maxCoeff(), 1e-11 * K2.cwiseAbs().maxCoeff());
}

TEST(TensorMassCutting, ElementByElementFieldsEqualARebuild) {
  for (const char* field :
       {R"(StandardTetrahedralFEMForceField name="field" materialName="StVenantKirchhoff" )"
        R"(youngModulus="5000" poissonRatio="0.35")",
        R"(StandardTetrahedralFEMForceField name="field" materialName="NeoHookean" )"
        R"(youngModulus="5000" poissonRatio="0.35")",
        R"(TetrahedralVolumePenaltyForceField name="field" stiffness="2000")"}) {
    SCOPED_TRACE(field);
    SceneHolder cut, rebuilt;
    cutAndRebuild(cut, rebuilt, field, kBatches);
    std::string text;
    const auto x = numbers(cut.text("@dofs.position"));
    for (std::size_t i = 0; i < x.size(); ++i)
      text += std::to_string(x[i] * (1 + 0.05 * std::sin(double(i)))) + " ";
    cut.set("@dofs.position", text);
    rebuilt.set("@dofs.position", text);
    ForceFieldChecker ca(cut.scene(), cut.root()), cb(rebuilt.scene(), rebuilt.root());
    const Eigen::VectorXd f1 = ca.force(), f2 = cb.force();
    EXPECT_LT((f1 - f2).cwiseAbs().maxCoeff(), 1e-11 * f2.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd K1 = ca.assembled(0, 0, 1), K2 = cb.assembled(0, 0, 1);
    EXPECT_LT((K1 - K2).cwiseAbs().maxCoeff(), 1e-11 * K2.cwiseAbs().maxCoeff());
  }
}

TEST(TensorMassCutting, AThousandRemovalsDoNotGrowTheMemory) {
  for (const char* field :
       {"TetrahedralTensorMassForceField", "TetrahedralStVKTensorMassForceField"}) {
    SCOPED_TRACE(field);
    SceneHolder s;
    // 40 x 2 x 2 cubes: 960 tetrahedra... and 1000 removals need more: 45 cubes long, 1080.
    ASSERT_TRUE(s.load(block(field, 45)));
    auto* modifier =
        component<TetrahedronSetTopologyModifier>(s, "@modifier", "TetrahedronSetTopologyModifier");
    ASSERT_TRUE(modifier);
    ForceFieldChecker checker(s.scene(), s.root());
    checker.force();
    std::size_t capacity = 0;
    auto measure = [&]() -> std::size_t {
      Base* b = s.get<Base>("@field");
      if (b->className() == "TetrahedralTensorMassForceField") {
        const auto& t = static_cast<TetrahedralTensorMassForceField*>(b)->tensors();
        return t.vertexTensors.capacity() + t.edges.capacity() + t.edgeTensors.capacity();
      }
      const auto& m = static_cast<TetrahedralStVKTensorMassForceField*>(b)->model();
      return m.vertices.capacity() + m.edges.capacity() + m.edgeTerms.capacity() +
             m.triangles.capacity() + m.triangleTerms.capacity() + m.tetrahedra.capacity() +
             m.tetrahedronTerms.capacity() + m.triangleEdges.capacity() +
             m.tetrahedronEdges.capacity();
    };
    capacity = measure();
    const Topology* topology = s.get<Topology>("@topology");
    for (int k = 0; k < 1000; ++k) {
      // Every 7th tetrahedron of what remains, from the middle: single removals.
      const auto n = static_cast<Index>(topology->tetrahedra().size());
      const std::vector<Index> one{static_cast<Index>((7u * static_cast<unsigned>(k)) % n)};
      ASSERT_TRUE(modifier->removeTetrahedra(one));
      const Eigen::VectorXd f = checker.force();
      ASSERT_TRUE(f.allFinite());
      ASSERT_LE(measure(), capacity) << "after " << k + 1 << " removals";
    }
    EXPECT_EQ(topology->tetrahedra().size(), 80u);
  }
}

}  // namespace
}  // namespace stroma::test
