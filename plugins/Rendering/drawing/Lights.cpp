// SPDX-License-Identifier: MIT
#include "Lights.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "SceneReading.h"
#include "core/Base.h"
#include "core/Node.h"

namespace stroma::rendering {

namespace {

void setLightColor(GLenum light, GLenum which, const Vec4d& c) {
  const GLfloat v[4] = {static_cast<GLfloat>(c[0]), static_cast<GLfloat>(c[1]),
                        static_cast<GLfloat>(c[2]), static_cast<GLfloat>(c[3])};
  glLightfv(light, which, v);
}

Vec3d vector3(const Base& object, const char* name, const Vec3d& fallback) {
  std::vector<double> v;
  if (readNumbers(object, name, v) && v.size() == 3 && Vec3d(v[0], v[1], v[2]).allFinite())
    return Vec3d(v[0], v[1], v[2]);
  return fallback;
}

double number(const Base& object, const char* name, double fallback) {
  std::vector<double> v;
  return readNumbers(object, name, v) && v.size() == 1 && std::isfinite(v[0]) ? v[0] : fallback;
}

}  // namespace

int setupLights(const Node& root) {
  std::vector<const Base*> lights;
  const Base* manager = nullptr;
  forEachObject(root, [&](Base& object) {
    const std::string& c = object.className();
    if (c == "DirectionalLight" || c == "PositionalLight" || c == "SpotLight")
      lights.push_back(&object);
    if (c == "LightManager" && !manager) manager = &object;
  });
  GLint maxLights = 8;
  glGetIntegerv(GL_MAX_LIGHTS, &maxLights);
  for (int i = 0; i < maxLights; ++i) glDisable(GL_LIGHT0 + i);
  glEnable(GL_LIGHTING);

  Vec4d ambient(0.15, 0.15, 0.15, 1.0);
  if (manager) parseColor(readText(*manager, "ambient"), ambient);
  const GLfloat model[4] = {static_cast<GLfloat>(ambient[0]), static_cast<GLfloat>(ambient[1]),
                            static_cast<GLfloat>(ambient[2]), 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);

  if (lights.empty()) {
    // A headlight: fixed to the eye, so that whatever the camera looks at is lit.
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    const GLfloat towardsEye[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, towardsEye);
    glPopMatrix();
    setLightColor(GL_LIGHT0, GL_AMBIENT, Vec4d(0, 0, 0, 1));
    setLightColor(GL_LIGHT0, GL_DIFFUSE, Vec4d(0.85, 0.85, 0.85, 1));
    setLightColor(GL_LIGHT0, GL_SPECULAR, Vec4d(0.4, 0.4, 0.4, 1));
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
    glEnable(GL_LIGHT0);
    return 0;
  }

  int used = 0;
  for (const Base* light : lights) {
    if (used >= maxLights) break;
    const GLenum id = GL_LIGHT0 + used++;
    Vec4d color(1, 1, 1, 1);
    parseColor(readText(*light, "color"), color);
    color[3] = 1.0;
    setLightColor(id, GL_AMBIENT, Vec4d(0, 0, 0, 1));
    setLightColor(id, GL_DIFFUSE, color);
    setLightColor(id, GL_SPECULAR, color);
    const std::string& kind = light->className();
    const Vec3d direction = vector3(*light, "direction", Vec3d(0, 0, -1));
    if (kind == "DirectionalLight") {
      // `direction` is where the light goes; OpenGL wants the direction towards the light.
      const GLfloat towardsLight[4] = {static_cast<GLfloat>(-direction[0]),
                                       static_cast<GLfloat>(-direction[1]),
                                       static_cast<GLfloat>(-direction[2]), 0.0f};
      glLightfv(id, GL_POSITION, towardsLight);
      glLightf(id, GL_SPOT_CUTOFF, 180.0f);
    } else {
      const Vec3d p = vector3(*light, "position", Vec3d::Zero());
      const GLfloat position[4] = {static_cast<GLfloat>(p[0]), static_cast<GLfloat>(p[1]),
                                   static_cast<GLfloat>(p[2]), 1.0f};
      glLightfv(id, GL_POSITION, position);
      glLightf(id, GL_LINEAR_ATTENUATION,
               static_cast<GLfloat>(std::max(0.0, number(*light, "attenuation", 0.0))));
      if (kind == "SpotLight") {
        const GLfloat d[3] = {static_cast<GLfloat>(direction[0]),
                              static_cast<GLfloat>(direction[1]),
                              static_cast<GLfloat>(direction[2])};
        glLightfv(id, GL_SPOT_DIRECTION, d);
        glLightf(id, GL_SPOT_CUTOFF,
                 static_cast<GLfloat>(std::clamp(number(*light, "cutoff", 30.0), 0.0, 90.0)));
        glLightf(id, GL_SPOT_EXPONENT,
                 static_cast<GLfloat>(std::clamp(number(*light, "exponent", 20.0), 0.0, 128.0)));
      } else {
        glLightf(id, GL_SPOT_CUTOFF, 180.0f);
      }
    }
    glEnable(id);
  }
  return used;
}

}  // namespace stroma::rendering
