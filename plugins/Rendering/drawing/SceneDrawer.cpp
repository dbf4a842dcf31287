// SPDX-License-Identifier: MIT
#include "stroma/rendering/SceneDrawer.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "GlPrimitives.h"
#include "Legend.h"
#include "Lights.h"
#include "SceneDecorations.h"
#include "SceneReading.h"
#include "Textures.h"
#include "collision/CollisionModel.h"
#include "collision/CollisionPipeline.h"
#include "core/BaseState.h"
#include "core/Node.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "simulation/MechanicalState.h"
#include "simulation/VisualModel.h"
#include "topology/Topology.h"

namespace stroma::rendering {

namespace {

// Colors of what has no color of its own in the scene.
const Vec4d kElementColor(0.85, 0.45, 0.40, 1.0);    // FEM meshes: tissue pink
const Vec4d kStateColor(0.95, 0.90, 0.55, 1.0);      // points of mechanical states
const Vec4d kFixedColor(0.25, 0.85, 1.0, 1.0);       // fixed points
const Vec4d kCollisionColor(0.55, 0.85, 0.45, 1.0);  // collision models
const Vec4d kContactColor(1.0, 0.15, 0.15, 1.0);
const Vec4d kDefaultBackground(0.12, 0.13, 0.16, 1.0);

/// The faces that show a topology's elements from outside: the boundary triangles of its
/// tetrahedra, else the boundary quads of its hexahedra (split in two), else its triangles and
/// quads.
std::vector<Vec3i> elementSurface(const Topology& topology) {
  std::vector<Vec3i> out;
  auto addQuad = [&](const Quad& q) {
    out.emplace_back(q[0], q[1], q[2]);
    out.emplace_back(q[0], q[2], q[3]);
  };
  if (!topology.tetrahedra().empty()) {
    for (const Triangle& t : topology.boundaryTriangles()) out.emplace_back(t[0], t[1], t[2]);
  } else if (!topology.hexahedra().empty()) {
    for (const Quad& q : topology.boundaryQuads()) addQuad(q);
  } else {
    for (const Triangle& t : topology.triangles()) out.emplace_back(t[0], t[1], t[2]);
    for (const Quad& q : topology.quads()) addQuad(q);
  }
  return out;
}

/// Positions of a state as points in space (frames by their origins); empty below 3D.
std::vector<Vec3d> statePoints(const BaseState& state) {
  std::vector<Vec3d> out;
  const int dim = state.coordDimension();
  if (dim < 3) return out;
  std::vector<double> coords;
  state.copyPositions(coords);
  for (std::size_t i = 0; i + 3 <= coords.size(); i += static_cast<std::size_t>(dim))
    out.emplace_back(coords[i], coords[i + 1], coords[i + 2]);
  return out;
}

bool underAny(const Node* node, const std::set<const Node*>& nodes) {
  for (const Node* n = node; n; n = n->parent())
    if (nodes.count(n)) return true;
  return false;
}

}  // namespace

struct SceneDrawer::Impl {
  TextureCache textures;
  std::map<const Node*, DisplayFlags> nodeFlags;  ///< this frame's flags at each active node
  DisplayFlags defaultFlags;
  std::set<const Base*> warned;  ///< components already warned about (once each)
  std::vector<PointField> fields;

  void warnOnce(const Base& object, const std::string& text, const std::string& field = {}) {
    if (warned.insert(&object).second) object.msgWarning(text, field);
  }
};

SceneDrawer::SceneDrawer(Node& root) : m_root(root), m_impl(std::make_unique<Impl>()) {}
SceneDrawer::~SceneDrawer() = default;

DisplayFlags SceneDrawer::effectiveFlags() const {
  if (m_options.flags) return *m_options.flags;
  std::string unknown;
  return sceneDisplayFlags(m_root, unknown);
}

DisplayFlags SceneDrawer::collectNodeFlags() {
  m_impl->nodeFlags.clear();
  DisplayFlags any;
  any.visualModels = false;
  std::vector<std::pair<const Node*, DisplayFlags>> stack{{&m_root, DisplayFlags{}}};
  while (!stack.empty()) {
    auto [node, flags] = stack.back();
    stack.pop_back();
    if (!node->d_activated.value()) continue;
    if (m_options.flags) {
      flags = *m_options.flags;
    } else {
      for (const auto& object : node->objects())
        if (object->className() == "VisualStyle") {
          std::string unknown;
          flags.apply(readText(*object, "displayFlags"), unknown);
          if (!unknown.empty())
            m_impl->warnOnce(*object, "display flags not understood, ignored: " + unknown,
                             "displayFlags");
        }
    }
    m_impl->nodeFlags[node] = flags;
    any.visualModels |= flags.visualModels;
    any.behaviorModels |= flags.behaviorModels;
    any.forceFields |= flags.forceFields;
    any.collisionModels |= flags.collisionModels;
    any.wireframe |= flags.wireframe;
    for (const auto& child : node->children()) stack.emplace_back(child.get(), flags);
  }
  return any;
}

const DisplayFlags& SceneDrawer::flagsAt(const Node* node) const {
  auto it = m_impl->nodeFlags.find(node);
  return it == m_impl->nodeFlags.end() ? m_impl->defaultFlags : it->second;
}

Vec4d SceneDrawer::backgroundColor() const {
  Vec4d color = kDefaultBackground;
  if (const Base* background = findByClass(m_root, "BackgroundSetting")) {
    const std::string text = readText(*background, "color");
    if (!text.empty() && !parseColor(text, color))
      m_impl->warnOnce(*background,
                       "color '" + text +
                           "' is not 'r g b [a]' nor a color name; "
                           "the default background is used",
                       "color");
  }
  return color;
}

void SceneDrawer::updateVisuals() {
  forEachObject(m_root, [](Base& object) {
    if (auto* visual = dynamic_cast<VisualModel*>(&object)) visual->updateVisual();
  });
}

void SceneDrawer::releaseGLResources() { m_impl->textures.release(); }

void SceneDrawer::draw(const Camera& camera, int width, int height) {
  m_report = {};
  updateVisuals();
  const DisplayFlags any = collectNodeFlags();
  const Vec4d background = backgroundColor();
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;

  glViewport(0, 0, width, height);
  glClearColor(static_cast<GLfloat>(background[0]), static_cast<GLfloat>(background[1]),
               static_cast<GLfloat>(background[2]), static_cast<GLfloat>(background[3]));
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(camera.projectionMatrix(aspect).data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(camera.viewMatrix().data());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_COLOR_MATERIAL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  setupLights(m_root);

  // Bodies colored by a field replace their visual models (which would hide the colors).
  std::set<const Node*> coloredNodes;
  if (m_options.colorMap != ColorMapKind::none) {
    if (computePointFields(m_root, m_options.colorMap, m_impl->fields, m_report.colorMapError)) {
      fieldRange(m_impl->fields, m_report.colorMin, m_report.colorMax);
      for (const PointField& f : m_impl->fields)
        if (f.state && f.state->node()) coloredNodes.insert(f.state->node());
      drawColoredBodies();
    }
  }
  if (any.visualModels) drawVisualModels(coloredNodes);
  if (any.forceFields) drawElementMeshes(coloredNodes);
  if (any.behaviorModels) drawStates();
  if (any.collisionModels) drawCollisionModels();
  drawDecorations(background, width, height);

  if (m_report.colorMapped && m_options.legend) {
    const LegendPlacement placed =
        drawLegend(m_options.colorMap, m_report.colorMin, m_report.colorMax, width, height);
    m_report.legendMin = placed.minText;
    m_report.legendMax = placed.maxText;
    m_report.legendMinX = placed.minX;
    m_report.legendMinY = placed.minY;
    m_report.legendMaxX = placed.maxX;
    m_report.legendMaxY = placed.maxY;
    m_report.legendScale = placed.scale;
  }
  // Leave the camera's matrices loaded for whoever draws next (a viewer's picking spring).
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(camera.projectionMatrix(aspect).data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(camera.viewMatrix().data());
}

void SceneDrawer::drawDecorations(const Vec4d& background, int width, int height) {
  // Grids and axes are drawn with the visual models; labels over everything, before the legend.
  std::vector<const Base*> labels;
  forEachObject(m_root, [&](Base& object) {
    if (!flagsAt(object.node()).visualModels) return;
    m_report.lines += drawWorldDecoration(object);
    if (object.className() == "OglLabel") labels.push_back(&object);
  });
  for (const Base* label : labels) drawScreenLabel(*label, background, width, height);
}

void SceneDrawer::drawColoredBodies() {
  const double range = m_report.colorMax - m_report.colorMin;
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  setColorMaterial(Vec4d(1, 1, 1, 1));
  for (const PointField& field : m_impl->fields) {
    const auto* state = dynamic_cast<const MechanicalState<Vec3Types>*>(field.state);
    if (!state) continue;
    const auto& x = state->readCoord(VecId::position());
    if (x.size() != field.values.size()) continue;
    std::vector<Vec3d> colors(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      colors[i] = rampColor(range > 0 ? (field.values[i] - m_report.colorMin) / range : 0.5);
    const DisplayFlags& flags = flagsAt(state->node());
    const Topology* topology = state->node() ? state->node()->get<Topology>() : nullptr;
    const std::vector<Vec3i> faces = topology ? elementSurface(*topology) : std::vector<Vec3i>{};
    if (faces.empty()) {
      glDisable(GL_LIGHTING);
      glPointSize(4.0f);
      glBegin(GL_POINTS);
      for (std::size_t i = 0; i < x.size(); ++i) {
        glColor3d(colors[i][0], colors[i][1], colors[i][2]);
        glVertex3d(x[i][0], x[i][1], x[i][2]);
      }
      glEnd();
      glEnable(GL_LIGHTING);
      m_report.points += x.size();
    } else if (flags.wireframe) {
      glDisable(GL_LIGHTING);
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      m_report.lines += 3 * drawTriangles(x, {}, faces, colors);
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
      glEnable(GL_LIGHTING);
    } else {
      m_report.triangles += drawTriangles(x, vertexNormals(x, faces), faces, colors);
    }
    m_report.colorMapped = true;
  }
  glDisable(GL_COLOR_MATERIAL);
}

void SceneDrawer::drawVisualModels(const std::set<const Node*>& skipped) {
  forEachObject(m_root, [&](Base& object) {
    const auto* visual = dynamic_cast<const VisualModel*>(&object);
    if (!visual || underAny(object.node(), skipped)) return;
    const DisplayFlags& flags = flagsAt(object.node());
    if (!flags.visualModels) return;
    const VisualSurface* surface = visual->surface();
    if (!surface || surface->triangles.empty()) return;
    ++m_report.visualSurfaces;
    const VisualMaterial& m = surface->material;
    setMaterial(m.ambient, m.diffuse, m.specular, m.emissive, m.shininess);
    if (flags.wireframe) {
      glDisable(GL_LIGHTING);
      m_report.lines += drawTriangleEdges(surface->positions, surface->triangles);
      glEnable(GL_LIGHTING);
      return;
    }
    unsigned texture = 0;
    if (!surface->texture.empty()) {
      std::string error;
      texture = m_impl->textures.textureFor(surface->texture, error);
      if (!texture && !error.empty())
        m_impl->warnOnce(
            object,
            "texture '" + surface->texture + "' cannot be read (" + error + "); drawn without it",
            "texturename");
      if (texture && surface->texcoords.size() != surface->positions.size()) texture = 0;
    }
    if (texture) {
      glEnable(GL_TEXTURE_2D);
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
    if (surface->alphaBlend) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    const bool hasNormals = surface->normals.size() == surface->positions.size();
    const std::vector<Vec3d> computed =
        hasNormals ? std::vector<Vec3d>{} : vertexNormals(surface->positions, surface->triangles);
    m_report.triangles += drawTriangles(
        surface->positions, hasNormals ? surface->normals : computed, surface->triangles, {},
        texture ? std::span<const Vec2d>(surface->texcoords) : std::span<const Vec2d>());
    if (texture) {
      glBindTexture(GL_TEXTURE_2D, 0);
      glDisable(GL_TEXTURE_2D);
    }
    glDisable(GL_BLEND);
  });
}

void SceneDrawer::drawElementMeshes(const std::set<const Node*>& skipped) {
  // One mesh per node that has a force field, a 3D state and a topology with elements.
  std::vector<const Node*> nodes;
  std::vector<const Node*> stack{&m_root};
  while (!stack.empty()) {
    const Node* node = stack.back();
    stack.pop_back();
    if (!node->d_activated.value()) continue;
    nodes.push_back(node);
    for (const auto& child : node->children()) stack.push_back(child.get());
  }
  setColorMaterial(kElementColor);
  for (const Node* node : nodes) {
    const DisplayFlags& flags = flagsAt(node);
    if (!flags.forceFields || skipped.count(node) || !node->get<BaseForceField>()) continue;
    const auto* state = node->get<MechanicalState<Vec3Types>>();
    const Topology* topology = node->get<Topology>();
    if (!state || !topology) continue;
    const auto& x = state->readCoord(VecId::position());
    const std::vector<Vec3i> faces = elementSurface(*topology);
    if (flags.wireframe) {
      glDisable(GL_LIGHTING);
      m_report.lines += drawTriangleEdges(x, faces);
      glEnable(GL_LIGHTING);
    } else {
      m_report.triangles += drawTriangles(x, vertexNormals(x, faces), faces);
    }
  }
}

void SceneDrawer::drawStates() {
  glDisable(GL_LIGHTING);
  forEachObject(m_root, [&](Base& object) {
    if (!flagsAt(object.node()).behaviorModels) return;
    if (const auto* state = dynamic_cast<const BaseState*>(&object)) {
      glColor4d(kStateColor[0], kStateColor[1], kStateColor[2], 1.0);
      m_report.points += drawPoints(statePoints(*state), 3.0);
      return;
    }
    // Fixed points: SOFA's FixedProjectiveConstraint (FixedConstraint), PartialFixed...,
    // BoxConstraint (fixed points chosen by boxes), by class name and their `indices`.
    const std::string& kind = object.className();
    const bool fixes = kind.find("Fixed") != std::string::npos || kind == "BoxConstraint";
    if (!fixes || !object.findData("indices") || !object.node()) return;
    const BaseState* state = object.node()->get<BaseState>();
    if (!state) return;
    const std::vector<Vec3d> points = statePoints(*state);
    std::vector<Vec3d> fixed;
    const std::string fixAll = readText(object, "fixAll");
    if (fixAll == "1" || fixAll == "true") {
      fixed = points;
    } else {
      std::vector<double> indices;
      readNumbers(object, "indices", indices);
      for (double i : indices)
        if (i >= 0 && i < static_cast<double>(points.size()))
          fixed.push_back(points[static_cast<std::size_t>(i)]);
    }
    glColor4d(kFixedColor[0], kFixedColor[1], kFixedColor[2], 1.0);
    m_report.points += drawPoints(fixed, 7.0);
  });
  glEnable(GL_LIGHTING);
}

void SceneDrawer::drawCollisionModels() {
  const auto* phase = m_root.get<CollisionPhase>();
  forEachObject(m_root, [&](Base& object) {
    auto* model = dynamic_cast<CollisionModel*>(&object);
    if (!model || !model->d_active.value()) return;
    const DisplayFlags& flags = flagsAt(object.node());
    if (!flags.collisionModels) return;
    // With a pipeline the geometry is that of the last detection (the contacts drawn match
    // it); without one nothing updates it, so do it here.
    if (!phase) model->updateGeometry();
    const CollisionGeometry& g = model->geometry();
    Vec4d color = kCollisionColor;
    parseColor(model->d_color.value(), color);
    setColorMaterial(color);
    switch (g.kind) {
      case PrimitiveKind::triangle: {
        std::vector<Vec3i> triangles;
        triangles.reserve(g.triangles.size());
        for (const auto& t : g.triangles)
          triangles.emplace_back(static_cast<int>(t[0]), static_cast<int>(t[1]),
                                 static_cast<int>(t[2]));
        if (flags.wireframe) {
          glDisable(GL_LIGHTING);
          m_report.lines += drawTriangleEdges(g.points, triangles);
          glEnable(GL_LIGHTING);
        } else {
          glEnable(GL_POLYGON_OFFSET_FILL);  // under a visual surface at the same place
          glPolygonOffset(1.0f, 1.0f);
          m_report.triangles +=
              drawTriangles(g.points, vertexNormals(g.points, triangles), triangles);
          glDisable(GL_POLYGON_OFFSET_FILL);
        }
        break;
      }
      case PrimitiveKind::line:
        glDisable(GL_LIGHTING);
        for (const auto& e : g.edges)
          if (e[0] < g.points.size() && e[1] < g.points.size()) {
            drawSegment(g.points[e[0]], g.points[e[1]]);
            ++m_report.lines;
          }
        glEnable(GL_LIGHTING);
        break;
      case PrimitiveKind::point:
        glDisable(GL_LIGHTING);
        m_report.points += drawPoints(g.points, 4.0);
        glEnable(GL_LIGHTING);
        break;
      case PrimitiveKind::sphere:
        // One radius for all, or one each (a model with fewer radii than centres draws those).
        for (std::size_t i = 0; i < g.points.size() && (g.radii.size() == 1 || i < g.radii.size());
             ++i) {
          drawSphere(g.points[i], g.radius(i));
          m_report.triangles += 12 * 8 * 2;
        }
        break;
      case PrimitiveKind::box:
        glDisable(GL_LIGHTING);
        for (const OrientedBox& box : g.boxes) {
          drawBoxEdges(box);
          m_report.lines += 12;
        }
        glEnable(GL_LIGHTING);
        break;
    }
  });
  if (!phase || !flagsAt(&m_root).collisionModels) return;
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);  // contacts are inside the surfaces they join: show them anyway
  glColor4d(kContactColor[0], kContactColor[1], kContactColor[2], 1.0);
  for (const ModelPairContacts& pair : phase->lastContacts())
    for (const Contact& c : pair.contacts) {
      drawSegment(c.point[0], c.point[1]);
      m_report.points += drawPoints(std::vector<Vec3d>{c.point[0], c.point[1]}, 5.0);
      ++m_report.lines;
      ++m_report.contacts;
    }
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
}

}  // namespace stroma::rendering
