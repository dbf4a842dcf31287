// SPDX-License-Identifier: MIT
#include "Textures.h"

#include <GL/gl.h>

#include "stroma/rendering/PngImage.h"

namespace stroma::rendering {

unsigned TextureCache::textureFor(const std::string& file, std::string& error) {
  if (auto it = m_textures.find(file); it != m_textures.end()) return it->second;
  Image image;
  std::string why;
  unsigned id = 0;
  if (!readPng(file, image, why)) {
    error = why;
  } else {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (image.width > maxSize || image.height > maxSize) {
      error = "the image is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
              " pixels, above this OpenGL's largest texture (" + std::to_string(maxSize) + ")";
    } else {
      // Image rows go from the top, OpenGL's t from the bottom: texture coordinates as OBJ
      // files write them (t = 0 at the bottom) then land on the right rows.
      flipRows(image);
      GLuint texture = 0;
      glGenTextures(1, &texture);
      glBindTexture(GL_TEXTURE_2D, texture);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, image.rgba.data());
      glBindTexture(GL_TEXTURE_2D, 0);
      id = texture;
    }
  }
  m_textures[file] = id;
  return id;
}

void TextureCache::release() {
  for (auto& [file, id] : m_textures)
    if (id) {
      GLuint texture = id;
      glDeleteTextures(1, &texture);
    }
  m_textures.clear();
}

}  // namespace stroma::rendering
