// SPDX-License-Identifier: MIT
// Texture images uploaded to the current OpenGL context, once per file.
#pragma once

#include <map>
#include <string>

namespace stroma::rendering {

class TextureCache {
 public:
  /// The OpenGL texture of `file`, read (PNG) and uploaded on first use; 0 when it cannot be
  /// read. `error` is set to why only on the first failed attempt for a file, so that the
  /// caller warns once.
  unsigned textureFor(const std::string& file, std::string& error);
  /// Deletes the uploaded textures (the context must be current).
  void release();

 private:
  std::map<std::string, unsigned> m_textures;  ///< 0 for a file that could not be read
};

}  // namespace stroma::rendering
