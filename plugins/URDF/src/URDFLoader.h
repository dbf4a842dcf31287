// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include <array>
#include <string_view>

#include "core/Base.h"
#include "core/Data.h"
#include "core/Types.h"
#include "simulation/SceneGenerator.h"

namespace stroma {

/// How URDFLoader enforces the joints' limits: `auto` as Lagrange multipliers when the scene
/// solves them (a constraint solver in the root node before the loader: FreeMotionAnimationLoop
/// with GenericConstraintSolver), else by projection.
enum class JointLimitMethod { automatic, lagrangian, projective, none };

template <>
struct EnumKeywords<JointLimitMethod> {
  static constexpr std::array<std::string_view, 4> names{"auto", "lagrangian", "projective",
                                                        "none"};
};

/// A robot from a URDF file (read by urdfdom), built in the scene as an articulated body in
/// reduced coordinates: a child node named after the robot holding
///   joints   MechanicalObject Vec1d, one value per moving joint (initially 0), in the order of
///            `jointNames` (the links' tree, depth first from the root link);
///   mass     ArticulatedBodyMass: the links' masses, centers of mass and inertias of the file,
///            and gravity (the scene's);
///   drive    JointActuatorForceField, when a joint has damping or friction in the file;
///   limits   when a revolute or prismatic joint has limits: JointLimitLagrangianConstraint
///            (Lagrange multipliers, its stop torques an output) or JointLimitConstraint (a
///            projective clamp), as `jointLimits` says;
///   links/   MechanicalObject Rigid3d (a frame per link) mapped by ArticulatedMapping, with a
///            child node per visual mesh (a mesh loader, an OglModel and a RigidMapping).
/// Relative mesh file names are relative to the URDF file; package://p/x is looked for as x and
/// p/x in the URDF's folder and those above it; a mesh found nowhere there is looked for by the
/// scene loader as p/x (relative to the scene, then on the data path, share/ included: a
/// package is a folder there). OBJ and STL meshes use MeshOBJLoader and MeshSTLLoader, other
/// formats MeshAssimpLoader; boxes, cylinders and spheres are drawn as their closed triangle
/// meshes (PrimitiveMeshes.h). With collisionModels, each <collision> mesh, box or cylinder
/// becomes a child node of links/ (its triangles, a Vec3d state, RigidMapping onto the link,
/// Triangle, Line and Point collision models) and each sphere a SphereCollisionModel on a mapped
/// point.
///
/// The base link is fixed at the origin (fixedBase, default), unless fixedBase is false or the
/// root joint is floating: then six joint values come first, x y z translations and rotations
/// about z, y, x (yaw, pitch, roll: URDF's angles), singular at pitch = +-90 degrees.
class URDFLoader final : public Base, public SceneGenerator {
 public:
  Data<FileName> d_filename{this, "filename", {}, "URDF file of the robot.", {.mustExist = true}};
  Data<bool> d_fixedBase{this, "fixedBase", true,
                         "Fix the base link at the origin; false: a floating base (6 joint "
                         "values first)."};
  Data<RigidCoord3> d_basePose{this, "basePose", RigidCoord3{},
                               "World frame of the root link ('x y z qx qy qz qw'), or of the "
                               "floating base's start.",
                               {.unit = "m"}};
  Data<std::vector<double>> d_initialJoints{
      this, "initialJoints", {},
      "Joint values at the start (nbJoints, in the order of jointNames); default: all 0."};
  Data<double> d_armature{this, "armature", 0.0,
                          "Rotor inertia reflected at every joint, added to the joint-space "
                          "mass (ArticulatedBodyMass armature).",
                          {.unit = "kg m^2", .min = 0.0}};
  Data<bool> d_collisionModels{
      this, "collisionModels", false,
      "Also build the links' <collision> meshes (and spheres) as collision models (plugin "
      "Collision: the scene needs a CollisionPipeline); their contact forces reach the joints "
      "through the mappings."};
  Data<double> d_contactStiffness{this, "contactStiffness", 10.0,
                                  "contactStiffness of those collision models.", {.min = 0.0}};
  Data<JointLimitMethod> d_jointLimits{
      this, "jointLimits", JointLimitMethod::automatic,
      "How the file's joint limits are enforced: lagrangian (JointLimitLagrangianConstraint: "
      "multipliers, solved with the contacts; the robot's solver then needs a constraint "
      "correction), projective (JointLimitConstraint: a clamp), none, or auto: lagrangian when "
      "the root node holds a constraint solver (FreeMotionAnimationLoop), else projective."};
  Data<std::vector<std::string>> d_jointNames{
      this, "jointNames", {}, "Name of each joint value, in the order of the joint state (output).",
      {.output = true}};

  bool generateScene(SceneElement& node) override;

 private:
  /// jointLimits, `auto` resolved.
  JointLimitMethod limitMethod() const;
};

}  // namespace stroma
