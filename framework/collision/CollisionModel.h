// SPDX-License-Identifier: MIT
// Collision models: the surfaces (points, segments, triangles, spheres, oriented boxes) that
// detection tests against each other. A model sits in a node beside the mechanical state whose
// points it uses (a Vec3d surface mapped from a body, or Rigid3d frames for spheres and boxes);
// the models, broad and
// narrow phases, intersection methods and responses live in plugins (plugins/Collision).
//
// Each step the pipeline asks every active model to updateGeometry(), then reads its
// geometry(): views over the model's own arrays, in world coordinates, that the intersection
// methods walk without a virtual call per primitive.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "collision/Aabb.h"
#include "core/Base.h"
#include "core/Data.h"
#include "core/Types.h"

namespace stroma {

class BaseMechanicalState;

/// What the primitives of a model are.
enum class PrimitiveKind { point, line, triangle, sphere, box };

const char* primitiveKindName(PrimitiveKind kind);

/// A box turned with a rigid frame: the points center + rotation * u with |u_k| <= halfExtents_k
/// (world coordinates; the columns of `rotation` are the box's axes in the world).
struct OrientedBox {
  Vec3d center = Vec3d::Zero();
  Mat3d rotation = Mat3d::Identity();
  Vec3d halfExtents = Vec3d::Ones();
};

/// A model's primitives at the current step, world coordinates. Only the spans of the model's
/// kind are filled: `points` always (every vertex, the sphere centers, or the box centers);
/// `edges` for lines; `triangles` for triangles; `radii` for spheres (one per sphere, or a single
/// one for all); `boxes` for boxes (one per frame). Indices in edges and triangles are into
/// `points`.
struct CollisionGeometry {
  PrimitiveKind kind = PrimitiveKind::point;
  std::span<const Vec3d> points;
  std::span<const std::array<std::uint32_t, 2>> edges;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  std::span<const double> radii;
  std::span<const OrientedBox> boxes;
  /// Triangle models: each triangle's unit normal (right-hand rule), for the side of a contact.
  std::span<const Vec3d> triangleNormals;
  /// Triangle models: which of its vertices and edges a triangle owns, so that a contact on a
  /// vertex or an edge shared by several triangles is kept once (bits 0-2: vertices 0-2, bits
  /// 3-5: edges (0,1), (1,2), (2,0)). Every vertex and edge has exactly one owner.
  std::span<const std::uint8_t> featureOwnership;
  /// Triangle models: whether a line (point) model of the same node over the same state tests
  /// the edges (vertices), as SOFA's surfaces have: then a contact on a triangle's edge (vertex)
  /// is left to it, and the triangle keeps only the contacts inside it.
  bool edgesElsewhere = false;
  bool verticesElsewhere = false;
  /// Triangle models: for each triangle and each of its edges k (vertices k, k + 1), the third
  /// vertex of the other triangle on that edge, or kNoVertex on a border. A contact on an edge
  /// is kept only where the edge is the closest part of the surface (the other triangle's
  /// interior is not closer).
  std::span<const std::uint32_t> triangleEdgeNeighbors;
  static constexpr std::uint32_t kNoVertex = ~std::uint32_t{0};
  /// The surface around each primitive, as lists in CSR form (the entries of primitive i are
  /// neighbors[neighborOffsets[i] .. neighborOffsets[i + 1]]): point models: the points joined
  /// to each point by an edge of the node's topology (LocalMinDistance); line models: the third
  /// vertex of each triangle around each edge (LocalMinDistance); triangle models: the points
  /// joined to each point by an edge of the triangles (a contact on a vertex is kept only where
  /// the vertex is the closest part of the surface). Empty without a topology.
  std::span<const std::uint32_t> neighborOffsets;
  std::span<const std::uint32_t> neighbors;

  std::size_t primitiveCount() const;
  double radius(std::size_t sphere) const { return radii.size() == 1 ? radii[0] : radii[sphere]; }
};

/// Base of every collision model, with the settings SOFA's scenes give them.
class CollisionModel : public Base {
 public:
  Data<bool> d_active{this, "active", true, "Whether detection includes this model at all."};
  Data<bool> d_moving{this, "moving", true,
                      "Whether its points move: a model that does not has its boxes computed "
                      "once."};
  Data<bool> d_simulated{this, "simulated", true,
                         "Whether its state is simulated (integrated by a solver): two models "
                         "that are both not simulated are never tested against each other."};
  Data<bool> d_selfCollision{this, "selfCollision", false,
                             "Test the model against itself and the other models of its node "
                             "(primitives that share a vertex are never tested)."};
  Data<double> d_contactDistance{this,
                                 "contactDistance",
                                 0.0,
                                 "Thickness added around this model's primitives: contacts "
                                 "start that much farther out.",
                                 {.unit = "m", .min = 0.0, .alias = "proximity"}};
  Data<double> d_contactStiffness{this,
                                  "contactStiffness",
                                  10.0,
                                  "Stiffness of penalty contacts, combined with the other "
                                  "model's as SOFA does (k = k1 k2 / d0, d0 the contact "
                                  "distance of the pair).",
                                  {.min = 0.0}};
  Data<double> d_contactFriction{this,
                                 "contactFriction",
                                 0.0,
                                 "Friction coefficient of its contacts (constraint responses).",
                                 {.min = 0.0}};
  Data<double> d_contactRestitution{this,
                                    "contactRestitution",
                                    0.0,
                                    "Restitution coefficient of its contacts (constraint "
                                    "responses).",
                                    {.min = 0.0, .max = 1.0}};
  Data<std::string> d_contactResponse{this, "contactResponse", "",
                                      "Response for this model's contacts, overriding the "
                                      "CollisionResponse's (empty: that one)."};
  Data<std::vector<int>> d_group{this,
                                 "group",
                                 {},
                                 "Collision groups: two models that share a group are never "
                                 "tested against each other."};
  Data<bool> d_bothSide{this, "bothSide", false,
                        "Triangles collide on both sides (default: only on the side of their "
                        "normal)."};
  Data<std::string> d_color{this, "color", "", "Viewers only: a name or 'r g b [a]'."};

  /// The state whose points the primitives use.
  virtual BaseMechanicalState* state() const = 0;
  /// Reads the state's current positions into the geometry (called once per step, before
  /// detection). Allocates nothing once warm.
  virtual void updateGeometry() = 0;
  const CollisionGeometry& geometry() const { return m_geometry; }

  /// The box of each primitive at the current geometry, enlarged by `margin` + the model's
  /// contactDistance (+ radius for spheres; an oriented box gives the axis-aligned box around
  /// its 8 corners); `boxes` is resized.
  void computeBoxes(std::vector<Aabb>& boxes, double margin) const;

  /// Whether detection tests this model against `other` (or itself, `other` == this):
  /// both active, not both unsimulated, no shared group; models of one node (one object's
  /// points, lines and triangles, or the model itself) only when both ask for selfCollision.
  bool canCollideWith(const CollisionModel& other) const;

 protected:
  CollisionGeometry m_geometry;
};

}  // namespace stroma
