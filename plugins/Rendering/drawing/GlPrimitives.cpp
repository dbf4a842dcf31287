// SPDX-License-Identifier: MIT
#include "GlPrimitives.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace stroma::rendering {

namespace {

bool inRange(const Vec3i& t, std::size_t n) {
  return t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && static_cast<std::size_t>(t[0]) < n &&
         static_cast<std::size_t>(t[1]) < n && static_cast<std::size_t>(t[2]) < n;
}

void setColor4(GLenum which, const Vec4d& c) {
  const GLfloat v[4] = {static_cast<GLfloat>(c[0]), static_cast<GLfloat>(c[1]),
                        static_cast<GLfloat>(c[2]), static_cast<GLfloat>(c[3])};
  glMaterialfv(GL_FRONT_AND_BACK, which, v);
}

}  // namespace

std::vector<Vec3d> vertexNormals(std::span<const Vec3d> positions,
                                 std::span<const Vec3i> triangles) {
  std::vector<Vec3d> normals(positions.size(), Vec3d::Zero());
  for (const Vec3i& t : triangles) {
    if (!inRange(t, positions.size())) continue;
    // The cross product's length is twice the area: the weights come for free.
    const Vec3d n = (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  for (Vec3d& n : normals) {
    const double length = n.norm();
    n = length > 0 && std::isfinite(length) ? Vec3d(n / length) : Vec3d::Zero();
  }
  return normals;
}

std::size_t drawTriangles(std::span<const Vec3d> positions, std::span<const Vec3d> normals,
                          std::span<const Vec3i> triangles, std::span<const Vec3d> colors,
                          std::span<const Vec2d> texcoords) {
  const std::size_t n = positions.size();
  const bool hasNormals = normals.size() == n, hasColors = colors.size() == n,
             hasTex = texcoords.size() == n;
  std::size_t drawn = 0;
  glBegin(GL_TRIANGLES);
  for (const Vec3i& t : triangles) {
    if (!inRange(t, n)) continue;
    for (int k = 0; k < 3; ++k) {
      const int i = t[k];
      if (hasNormals) glNormal3d(normals[i][0], normals[i][1], normals[i][2]);
      if (hasColors) glColor3d(colors[i][0], colors[i][1], colors[i][2]);
      if (hasTex) glTexCoord2d(texcoords[i][0], texcoords[i][1]);
      glVertex3d(positions[i][0], positions[i][1], positions[i][2]);
    }
    ++drawn;
  }
  glEnd();
  return drawn;
}

std::size_t drawTriangleEdges(std::span<const Vec3d> positions, std::span<const Vec3i> triangles) {
  std::size_t drawn = 0;
  glBegin(GL_LINES);
  for (const Vec3i& t : triangles) {
    if (!inRange(t, positions.size())) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3d& a = positions[t[k]];
      const Vec3d& b = positions[t[(k + 1) % 3]];
      glVertex3d(a[0], a[1], a[2]);
      glVertex3d(b[0], b[1], b[2]);
      ++drawn;
    }
  }
  glEnd();
  return drawn;
}

std::size_t drawPoints(std::span<const Vec3d> positions, double size) {
  glPointSize(static_cast<GLfloat>(size));
  glBegin(GL_POINTS);
  for (const Vec3d& p : positions) glVertex3d(p[0], p[1], p[2]);
  glEnd();
  return positions.size();
}

void drawSegment(const Vec3d& a, const Vec3d& b) {
  glBegin(GL_LINES);
  glVertex3d(a[0], a[1], a[2]);
  glVertex3d(b[0], b[1], b[2]);
  glEnd();
}

void drawSphere(const Vec3d& center, double radius) {
  constexpr int kSlices = 12, kStacks = 8;
  constexpr double kPi = 3.14159265358979323846;
  for (int s = 0; s < kStacks; ++s) {
    const double t0 = kPi * s / kStacks, t1 = kPi * (s + 1) / kStacks;
    glBegin(GL_QUAD_STRIP);
    for (int k = 0; k <= kSlices; ++k) {
      const double phi = 2 * kPi * k / kSlices;
      // Lower ring first: each quad then turns counterclockwise seen from outside (front
      // facing, so that two-sided lighting keeps the outward normal).
      for (double theta : {t1, t0}) {
        const Vec3d n(std::sin(theta) * std::cos(phi), std::cos(theta),
                      std::sin(theta) * std::sin(phi));
        const Vec3d p = center + radius * n;
        glNormal3d(n[0], n[1], n[2]);
        glVertex3d(p[0], p[1], p[2]);
      }
    }
    glEnd();
  }
}

void drawBoxEdges(const OrientedBox& box) {
  Vec3d corner[8];
  for (int i = 0; i < 8; ++i) {
    const Vec3d u((i & 1 ? 1 : -1) * box.halfExtents[0], (i & 2 ? 1 : -1) * box.halfExtents[1],
                  (i & 4 ? 1 : -1) * box.halfExtents[2]);
    corner[i] = box.center + box.rotation * u;
  }
  glBegin(GL_LINES);
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) {
        glVertex3d(corner[i][0], corner[i][1], corner[i][2]);
        glVertex3d(corner[i | bit][0], corner[i | bit][1], corner[i | bit][2]);
      }
  glEnd();
}

void setMaterial(const Vec4d& ambient, const Vec4d& diffuse, const Vec4d& specular,
                 const Vec4d& emissive, double shininess) {
  setColor4(GL_AMBIENT, ambient);
  setColor4(GL_DIFFUSE, diffuse);
  setColor4(GL_SPECULAR, specular);
  setColor4(GL_EMISSION, emissive);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS,
              static_cast<GLfloat>(std::clamp(shininess, 0.0, 128.0)));
  glColor4d(diffuse[0], diffuse[1], diffuse[2], diffuse[3]);
}

void setColorMaterial(const Vec4d& color) {
  const Vec4d ambient(color[0] / 3, color[1] / 3, color[2] / 3, color[3]);
  setMaterial(ambient, color, Vec4d(0.2, 0.2, 0.2, 1), Vec4d(0, 0, 0, 1), 20);
}

PixelSpace::PixelSpace(int width, int height) {
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, width, height, 0, -1, 1);  // pixels, y downwards
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
}

PixelSpace::~PixelSpace() {
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopAttrib();
}

}  // namespace stroma::rendering
