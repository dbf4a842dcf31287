// SPDX-License-Identifier: MIT
#include "URDFLoader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>

#include "KinematicTree.h"
#include "PrimitiveMeshes.h"
#include "core/Node.h"
#include "simulation/Constraints.h"

namespace stroma {

namespace fs = std::filesystem;

namespace {

// urdfdom reports through console_bridge: its errors are collected for our message instead of
// going to the console. (console_bridge's handler is process-wide: scenes load one at a time.)
class CollectedMessages final : public console_bridge::OutputHandler {
 public:
  CollectedMessages() { console_bridge::useOutputHandler(this); }
  ~CollectedMessages() override { console_bridge::restorePreviousOutputHandler(); }
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) texts.push_back(text);
  }
  std::vector<std::string> texts;
};

std::string number(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

std::string vec3(const Vec3d& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

Vec3d toVec(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

RigidCoord3 toFrame(const urdf::Pose& p) {
  RigidCoord3 f;
  f.center = toVec(p.position);
  f.orientation = Quat(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized();
  return f;
}

std::string frameText(const RigidCoord3& f) {
  const Quat& q = f.orientation;
  return vec3(f.center) + " " + number(q.x()) + " " + number(q.y()) + " " + number(q.z()) + " " +
         number(q.w());
}

SceneElement element(std::string tag, std::vector<SceneAttribute> attributes) {
  SceneElement e;
  e.tag = std::move(tag);
  e.attributes = std::move(attributes);
  return e;
}

template <class T, class F>
std::string joined(const std::vector<T>& values, F&& text) {
  std::string out;
  for (const T& v : values) {
    if (!out.empty()) out += "  ";
    out += text(v);
  }
  return out;
}

// The file a URDF mesh names: file://, package://, relative to the URDF's folder.
fs::path findMesh(const std::string& name, const fs::path& urdfDir) {
  std::error_code ec;
  std::string path = name;
  if (path.rfind("file://", 0) == 0) path = path.substr(7);
  std::vector<fs::path> candidates;
  if (path.rfind("package://", 0) == 0) {
    const std::string rest = path.substr(10);  // package/inside
    const auto slash = rest.find('/');
    const std::string inside = slash == std::string::npos ? rest : rest.substr(slash + 1);
    for (fs::path dir = urdfDir; !dir.empty(); dir = dir.parent_path()) {
      candidates.push_back(dir / inside);
      candidates.push_back(dir / rest);
      if (dir == dir.parent_path()) break;
    }
  } else {
    candidates.push_back(fs::path(path).is_absolute() ? fs::path(path) : urdfDir / path);
  }
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c, ec)) return fs::absolute(c, ec);
  return {};
}

// A mesh's name as the data path holds it: package://p/x is p/x (a package is a folder on the
// data path), file://x is x.
fs::path nameOnDataPath(const std::string& name) {
  if (name.rfind("file://", 0) == 0) return name.substr(7);
  if (name.rfind("package://", 0) == 0) return name.substr(10);
  return name;
}

std::string meshLoaderFor(const fs::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") return "MeshOBJLoader";
  if (ext == ".stl") return "MeshSTLLoader";
  return "MeshAssimpLoader";
}

// One link of the tree being numbered, with the joint from its parent.
struct TreeLink {
  urdf::LinkConstSharedPtr link;   // null for the virtual links of a floating joint
  std::string jointName;
  KinematicJoint joint;
  const urdf::Joint* urdfJoint = nullptr;
  std::string mimicJoint;  // the joint whose value this one follows (URDF's <mimic>), if any
};

// The six joints of a floating joint: x, y, z translations, then rotations about z, y, x.
void addFloatingJoints(std::vector<TreeLink>& links, int parent, const RigidCoord3& origin,
                       const std::string& name) {
  const char* names[] = {"_x", "_y", "_z", "_yaw", "_pitch", "_roll"};
  const Vec3d axes[] = {Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ(),
                        Vec3d::UnitZ(), Vec3d::UnitY(), Vec3d::UnitX()};
  for (int k = 0; k < 6; ++k) {
    TreeLink t;
    t.jointName = name + names[k];
    t.joint.parent = parent;
    t.joint.origin = k == 0 ? origin : RigidCoord3{};
    t.joint.axis = axes[k];
    t.joint.type = k < 3 ? JointType::prismatic : JointType::revolute;
    parent = static_cast<int>(links.size());
    links.push_back(std::move(t));
  }
}

// A box, cylinder or sphere of the file as a closed triangle mesh in its link's frame (placed
// by `origin`); false for another geometry.
bool primitiveMesh(const urdf::Geometry& geometry, const RigidCoord3& origin, PrimitiveMesh& mesh) {
  if (geometry.type == urdf::Geometry::BOX)
    mesh = boxMesh(toVec(static_cast<const urdf::Box&>(geometry).dim));
  else if (geometry.type == urdf::Geometry::CYLINDER) {
    const auto& c = static_cast<const urdf::Cylinder&>(geometry);
    mesh = cylinderMesh(c.radius, c.length);
  } else if (geometry.type == urdf::Geometry::SPHERE)
    mesh = sphereMesh(static_cast<const urdf::Sphere&>(geometry).radius);
  else
    return false;
  transformMesh(mesh, origin);
  return true;
}

std::string pointsText(const PrimitiveMesh& mesh) { return joined(mesh.points, vec3); }

std::string trianglesText(const PrimitiveMesh& mesh) {
  return joined(mesh.triangles, [](const Vec3i& t) {
    return std::to_string(t.x()) + " " + std::to_string(t.y()) + " " + std::to_string(t.z());
  });
}

// The <collision> meshes and spheres of the links as collision models attached to their link's
// frame (index i of links/frames).
void addCollisionNodes(SceneElement& linkNode, const std::vector<TreeLink>& links,
                       const fs::path& urdfDir, const std::string& stiffness) {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (!links[i].link) continue;
    int count = 0;
    for (const urdf::CollisionSharedPtr& collision : links[i].link->collision_array) {
      if (!collision || !collision->geometry) continue;
      const RigidCoord3 origin = toFrame(collision->origin);
      const std::string name =
          "collision_" + links[i].link->name + (count ? "_" + std::to_string(count) : "");
      SceneElement c = element("Node", {{"name", name}});
      const std::vector<SceneAttribute> mapping = {
          {"input", "@../frames"}, {"index", std::to_string(i)}};
      if (collision->geometry->type == urdf::Geometry::MESH) {
        const auto& mesh = static_cast<const urdf::Mesh&>(*collision->geometry);
        fs::path meshFile = findMesh(mesh.filename, urdfDir);
        if (meshFile.empty()) meshFile = nameOnDataPath(mesh.filename);
        double roll = 0, pitch = 0, yaw = 0;
        collision->origin.rotation.getRPY(roll, pitch, yaw);
        const double deg = 180.0 / M_PI;
        c.children.push_back(element(meshLoaderFor(meshFile),
                                     {{"name", "loader"},
                                      {"filename", meshFile.string()},
                                      {"scale3d", vec3(toVec(mesh.scale))},
                                      {"rotation", vec3(Vec3d(roll, pitch, yaw) * deg)},
                                      {"translation", vec3(origin.center)}}));
        c.children.push_back(element("MeshTopology", {{"name", "topology"}, {"src", "@loader"}}));
        c.children.push_back(element(
            "MechanicalObject", {{"name", "points"}, {"template", "Vec3d"}, {"src", "@loader"}}));
        c.children.push_back(element("RigidMapping", mapping));
        for (const char* model :
             {"TriangleCollisionModel", "LineCollisionModel", "PointCollisionModel"})
          c.children.push_back(element(model, {{"contactStiffness", stiffness}}));
      } else if (collision->geometry->type == urdf::Geometry::SPHERE) {
        const auto& sphere = static_cast<const urdf::Sphere&>(*collision->geometry);
        c.children.push_back(element("MechanicalObject", {{"name", "points"},
                                                          {"template", "Vec3d"},
                                                          {"position", vec3(origin.center)}}));
        c.children.push_back(element("RigidMapping", mapping));
        c.children.push_back(element(
            "SphereCollisionModel",
            {{"radius", number(sphere.radius)}, {"contactStiffness", stiffness}}));
      } else if (PrimitiveMesh shape; primitiveMesh(*collision->geometry, origin, shape)) {
        // A box or a cylinder: its closed triangle mesh, collided as a mesh file would be.
        c.children.push_back(element("MeshTopology", {{"name", "topology"},
                                                      {"position", pointsText(shape)},
                                                      {"triangles", trianglesText(shape)}}));
        c.children.push_back(element("MechanicalObject", {{"name", "points"},
                                                          {"template", "Vec3d"},
                                                          {"position", pointsText(shape)}}));
        c.children.push_back(element("RigidMapping", mapping));
        for (const char* model :
             {"TriangleCollisionModel", "LineCollisionModel", "PointCollisionModel"})
          c.children.push_back(element(model, {{"contactStiffness", stiffness}}));
      } else {
        continue;
      }
      linkNode.children.push_back(std::move(c));
      ++count;
    }
  }
}

}  // namespace

JointLimitMethod URDFLoader::limitMethod() const {
  if (d_jointLimits.value() != JointLimitMethod::automatic) return d_jointLimits.value();
  const bool solvesMultipliers = node() && node()->root().get<BaseConstraintSolver>() != nullptr;
  return solvesMultipliers ? JointLimitMethod::lagrangian : JointLimitMethod::projective;
}

bool URDFLoader::generateScene(SceneElement& node) {
  const fs::path file = d_filename.value().path();
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    msgError("cannot open '" + file.string() + "'", "filename");
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  urdf::ModelInterfaceSharedPtr model;
  std::string reasons;
  {
    CollectedMessages messages;
    try {
      model = urdf::parseURDF(text.str());
    } catch (const std::exception& e) {
      messages.texts.push_back(e.what());
    }
    for (const std::string& t : messages.texts) reasons += (reasons.empty() ? "" : "; ") + t;
  }
  if (!model) {
    // urdfdom's XML reader gives no line: tinyxml2 (the scene reader's) does, for XML errors.
    std::string line;
    tinyxml2::XMLDocument document;
    if (document.Parse(text.str().data(), text.str().size()) != tinyxml2::XML_SUCCESS)
      line = std::string(" (line ") + std::to_string(document.ErrorLineNum()) + ": " +
             document.ErrorName() + ")";
    msgError("'" + file.string() + "' is not a valid URDF robot: " +
                 (reasons.empty() ? std::string("urdfdom gave no reason") : reasons) + line,
             "filename");
    return false;
  }
  const std::string where = "'" + file.string() + "': ";

  // The links, depth first from the root; floating joints become six joint values.
  std::vector<TreeLink> links;
  {
    TreeLink root;
    root.link = model->getRoot();
    links.push_back(root);
  }
  if (!d_fixedBase.value()) {
    links.clear();
    TreeLink world;
    world.jointName = "world";
    links.push_back(world);
    addFloatingJoints(links, 0, RigidCoord3{}, "base");
    TreeLink root;
    root.link = model->getRoot();
    root.joint.parent = static_cast<int>(links.size()) - 1;
    root.jointName = "base";
    links.push_back(root);
  }
  std::function<bool(int)> addChildren = [&](int index) {
    const urdf::LinkConstSharedPtr link = links[index].link;
    for (const urdf::JointSharedPtr& j : link->child_joints) {
      const urdf::LinkConstSharedPtr child = model->getLink(j->child_link_name);
      if (!child) continue;
      TreeLink t;
      t.link = child;
      t.jointName = j->name;
      t.urdfJoint = j.get();
      t.joint.parent = index;
      t.joint.origin = toFrame(j->parent_to_joint_origin_transform);
      t.joint.axis = toVec(j->axis);
      switch (j->type) {
        case urdf::Joint::REVOLUTE:
        case urdf::Joint::CONTINUOUS: t.joint.type = JointType::revolute; break;
        case urdf::Joint::PRISMATIC: t.joint.type = JointType::prismatic; break;
        case urdf::Joint::FIXED: t.joint.type = JointType::fixed; break;
        case urdf::Joint::FLOATING: {
          addFloatingJoints(links, index, t.joint.origin, j->name);
          t.joint.parent = static_cast<int>(links.size()) - 1;
          t.joint.origin = RigidCoord3{};
          t.joint.type = JointType::fixed;
          t.urdfJoint = nullptr;
          break;
        }
        case urdf::Joint::PLANAR: {
          // Motion in the plane normal to the axis: two translations (values name_u, name_v
          // along u and v, axis = u x v) on virtual links, then the child turns about the axis.
          const Vec3d n = toVec(j->axis);
          if (n.norm() == 0) {
            t.joint.type = JointType::revolute;  // a zero axis: reported below
            break;
          }
          const Vec3d normal = n.normalized();
          const Vec3d u = normal.unitOrthogonal(), v = normal.cross(u);
          int parent = index;
          for (const auto& [suffix, direction] : {std::pair{"_u", u}, std::pair{"_v", v}}) {
            TreeLink slide;
            slide.jointName = j->name + suffix;
            slide.joint.parent = parent;
            slide.joint.origin = parent == index ? t.joint.origin : RigidCoord3{};
            slide.joint.axis = direction;
            slide.joint.type = JointType::prismatic;
            parent = static_cast<int>(links.size());
            links.push_back(std::move(slide));
          }
          t.joint.parent = parent;
          t.joint.origin = RigidCoord3{};
          t.joint.type = JointType::revolute;
          t.jointName = j->name + "_theta";
          t.urdfJoint = nullptr;  // its <limit> and <dynamics> are about the plane: not applied
          break;
        }
        default:
          msgError(where + "joint '" + j->name + "' is of unknown type: only revolute, "
                   "continuous, prismatic, fixed, floating and planar joints are supported",
                   "filename");
          return false;
      }
      if (j->mimic && t.joint.type != JointType::fixed) {
        t.mimicJoint = j->mimic->joint_name;
        t.joint.multiplier = j->mimic->multiplier;
        t.joint.offset = j->mimic->offset;
      }
      if (t.joint.type != JointType::fixed && toVec(j->axis).norm() == 0) {
        msgError(where + "joint '" + j->name + "' has a zero axis", "filename");
        return false;
      }
      links.push_back(t);
      if (!addChildren(static_cast<int>(links.size()) - 1)) return false;
  // Mimic joints follow the value of the joint they name (no value of their own).
  for (TreeLink& t : links) {
    if (t.mimicJoint.empty()) continue;
    for (std::size_t k = 0; k < links.size(); ++k)
      if (links[k].jointName == t.mimicJoint && links[k].mimicJoint.empty() &&
          links[k].joint.type != JointType::fixed)
        t.joint.mimic = static_cast<int>(k);
    if (t.joint.mimic < 0) {
      msgError(where + "joint '" + t.jointName + "' mimics '" + t.mimicJoint +
                   "', which is not a moving joint of the robot (nor a mimic one itself)",
               "filename");
      return false;
    }
  }
    }
    return true;
  };
  if (!addChildren(static_cast<int>(links.size()) - 1)) return false;

  // Masses and inertias, checked.
  const std::size_t n = links.size();
  std::vector<double> masses(n, 0.0), inertias(6 * n, 0.0);
  std::vector<Vec3d> centers(n, Vec3d::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    if (!links[i].link || !links[i].link->inertial) continue;
    const urdf::Inertial& inertial = *links[i].link->inertial;
    const std::string name = "link '" + links[i].link->name + "'";
    if (!(inertial.mass >= 0) || !std::isfinite(inertial.mass)) {
      msgError(where + name + " has mass " + number(inertial.mass) +
                   " (inertial/mass): it must be finite and non-negative",
               "filename");
      return false;
    }
    Mat3d I;
    I << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
        inertial.ixz, inertial.iyz, inertial.izz;
    const double smallest = Eigen::SelfAdjointEigenSolver<Mat3d>(I).eigenvalues().minCoeff();
    if (inertial.mass > 0 && (!I.allFinite() || !(smallest > 0))) {
      msgError(where + name + " has an inertia that is not positive definite (inertial/" +
                   "inertia, smallest eigenvalue " + number(smallest) + " kg m^2)",
               "filename");
      return false;
    }
    // The inertia is given in the inertial frame: turn it into the link's.
    const RigidCoord3 frame = toFrame(inertial.origin);
    const Mat3d R = frame.orientation.toRotationMatrix();
    const Mat3d L = R * I * R.transpose();
    masses[i] = inertial.mass;
    centers[i] = frame.center;
    const double values[6] = {L(0, 0), L(0, 1), L(0, 2), L(1, 1), L(1, 2), L(2, 2)};
    std::copy(values, values + 6, inertias.begin() + 6 * static_cast<long>(i));
  }

  // Joint values: names, damping and friction, limits.
  std::vector<std::string> jointNames;
  std::vector<double> damping, friction;
  std::vector<unsigned> limited;
  std::vector<double> lower, upper;
  bool anyDrive = false;
  for (const TreeLink& t : links) {
    if (t.joint.type == JointType::fixed || t.jointName.empty() || t.joint.mimic >= 0) continue;
    const unsigned dof = static_cast<unsigned>(jointNames.size());
    jointNames.push_back(t.jointName);
    const urdf::Joint* j = t.urdfJoint;
    damping.push_back(j && j->dynamics ? j->dynamics->damping : 0.0);
    friction.push_back(j && j->dynamics ? j->dynamics->friction : 0.0);
    anyDrive = anyDrive || damping.back() != 0 || friction.back() != 0;
    if (j && j->limits && j->type != urdf::Joint::CONTINUOUS &&
        j->limits->lower < j->limits->upper) {
      limited.push_back(dof);
      lower.push_back(j->limits->lower);
      upper.push_back(j->limits->upper);
    }
  }
  d_jointNames.setValue(jointNames);
  std::vector<double> initial = d_initialJoints.value();
  if (initial.empty()) initial.assign(jointNames.size(), 0.0);
  if (initial.size() != jointNames.size()) {
    msgError("has " + std::to_string(initial.size()) + " values for the " +
                 std::to_string(jointNames.size()) + " joint values of the robot",
             "initialJoints");
    return false;
  }

  // The subgraph.
  SceneElement robot = element("Node", {{"name", model->getName().empty() ? "robot"
                                                                          : model->getName()}});
  robot.children.push_back(element(
      "MechanicalObject",
      {{"name", "joints"},
       {"template", "Vec1d"},
       {"position", joined(initial, number)}}));
  robot.children.push_back(element(
      "ArticulatedBodyMass",
      {{"name", "mass"},
       {"mapping", "@links/mapping"},
       {"linkMasses", joined(masses, number)},
       {"centersOfMass", joined(centers, vec3)},
       {"inertias", joined(inertias, number)},
       {"armature", number(d_armature.value())}}));
  if (anyDrive)
    robot.children.push_back(element("JointActuatorForceField",
                                     {{"name", "drive"},
                                      {"damping", joined(damping, number)},
                                      {"friction", joined(friction, number)}}));
  if (!limited.empty() && limitMethod() != JointLimitMethod::none)
    robot.children.push_back(element(
        limitMethod() == JointLimitMethod::lagrangian ? "JointLimitLagrangianConstraint"
                                                      : "JointLimitConstraint",
        {{"name", "limits"},
         {"indices", joined(limited, [](unsigned v) { return std::to_string(v); })},
         {"lower", joined(lower, number)},
         {"upper", joined(upper, number)}}));

  std::vector<int> parents;
  std::vector<std::string> types;
  std::vector<RigidCoord3> origins;
  std::vector<Vec3d> axes;
  std::vector<int> mimic;
  std::vector<double> multipliers, offsets;
  bool anyMimic = false;
  for (const TreeLink& t : links) {
    mimic.push_back(t.joint.mimic);
    multipliers.push_back(t.joint.multiplier);
    offsets.push_back(t.joint.offset);
    anyMimic = anyMimic || t.joint.mimic >= 0;
    parents.push_back(t.joint.parent);
    types.push_back(t.joint.type == JointType::fixed       ? "fixed"
                    : t.joint.type == JointType::revolute  ? "revolute"
                                                           : "prismatic");
    origins.push_back(t.joint.origin);
    axes.push_back(t.joint.axis);
  }
  SceneElement linkNode = element("Node", {{"name", "links"}});
  linkNode.children.push_back(
      element("MechanicalObject", {{"name", "frames"}, {"template", "Rigid3d"}}));
  linkNode.children.push_back(element(
      "ArticulatedMapping",
      {{"name", "mapping"},
       {"input", "@../joints"},
       {"output", "@frames"},
       {"parents", joined(parents, [](int p) { return std::to_string(p); })},
       {"jointTypes", joined(types, [](const std::string& s) { return s; })},
       {"origins", joined(origins, frameText)},
       {"axes", joined(axes, vec3)},
       {"base", frameText(d_basePose.value())}}));
  if (anyMimic) {
    SceneElement& mapping = linkNode.children.back();
    mapping.attributes.push_back(
        {"mimic", joined(mimic, [](int m) { return std::to_string(m); })});
    mapping.attributes.push_back({"mimicMultipliers", joined(multipliers, number)});
    mapping.attributes.push_back({"mimicOffsets", joined(offsets, number)});
  }

  // Visual meshes, attached to their link's frame.
  const fs::path urdfDir = fs::absolute(file).parent_path();
  for (std::size_t i = 0; i < n; ++i) {
    if (!links[i].link) continue;
    int count = 0;
    for (const urdf::VisualSharedPtr& visual : links[i].link->visual_array) {
      if (!visual || !visual->geometry) continue;
      std::vector<SceneAttribute> model = {{"name", "visual"}};
      if (visual->material && visual->material->color.a > 0) {
        const urdf::Color& c = visual->material->color;
        model.push_back({"color", number(c.r) + " " + number(c.g) + " " + number(c.b) + " " +
                                      number(c.a)});
      }
      const std::string nodeName =
          "visual_" + links[i].link->name + (count ? "_" + std::to_string(count) : "");
      if (PrimitiveMesh shape; primitiveMesh(*visual->geometry, toFrame(visual->origin), shape)) {
        // A box, cylinder or sphere: its triangles, drawn as a mesh file would be.
        SceneElement v = element("Node", {{"name", nodeName}});
        model.push_back({"position", pointsText(shape)});
        model.push_back({"triangles", trianglesText(shape)});
        v.children.push_back(element("OglModel", model));
        v.children.push_back(element("RigidMapping", {{"input", "@../frames"},
                                                      {"output", "@visual"},
                                                      {"index", std::to_string(i)}}));
        linkNode.children.push_back(std::move(v));
        ++count;
        continue;
      }
      if (visual->geometry->type != urdf::Geometry::MESH) continue;
      const auto& mesh = static_cast<const urdf::Mesh&>(*visual->geometry);
      // Beside the URDF, else by the name inside the package on Stroma's data path (the scene
      // loader looks for it there and reports it when missing).
      fs::path meshFile = findMesh(mesh.filename, urdfDir);
      if (meshFile.empty()) meshFile = nameOnDataPath(mesh.filename);
      const RigidCoord3 origin = toFrame(visual->origin);
      double roll = 0, pitch = 0, yaw = 0;
      visual->origin.rotation.getRPY(roll, pitch, yaw);
      const double deg = 180.0 / M_PI;
      SceneElement v = element("Node", {{"name", nodeName}});
      v.children.push_back(element(meshLoaderFor(meshFile),
                                   {{"name", "loader"},
                                    {"filename", meshFile.string()},
                                    {"scale3d", vec3(toVec(mesh.scale))},
                                    {"rotation", vec3(Vec3d(roll, pitch, yaw) * deg)},
                                    {"translation", vec3(origin.center)}}));
      model.push_back({"src", "@loader"});
      v.children.push_back(element("OglModel", model));
      v.children.push_back(element("RigidMapping", {{"input", "@../frames"},
                                                    {"output", "@visual"},
                                                    {"index", std::to_string(i)}}));
      linkNode.children.push_back(std::move(v));
      ++count;
    }
  }
  if (d_collisionModels.value())
    addCollisionNodes(linkNode, links, urdfDir, number(d_contactStiffness.value()));
  robot.children.push_back(std::move(linkNode));
  node.children.push_back(std::move(robot));
  return true;
}

}  // namespace stroma
