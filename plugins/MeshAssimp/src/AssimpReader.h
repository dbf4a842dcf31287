// SPDX-License-Identifier: MIT
// Reading a mesh file through assimp into Stroma's plain mesh lists, free of components (the
// loader and the tests use it).
//
// Each placement of a mesh in the file's node tree becomes one AssimpMesh, with the product of
// the transforms from the root node down to its node applied to its points (and the inverse
// transpose to its normals): a mesh that two nodes hold comes out twice. Points are kept as
// assimp gives them: one per corner for formats that store them so (STL), the file's points
// otherwise, unless joinIdenticalVertices asks assimp to merge identical ones.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/Types.h"
#include "formats/MeshData.h"

namespace stroma {

struct AssimpReadOptions {
  /// Keep the quads as quads (assimp does not triangulate; polygons of five and more corners
  /// are split here as fans). Otherwise every polygon is triangulated by assimp.
  bool keepQuads = false;
  /// Merge the points that are identical in every attribute (aiProcess_JoinIdenticalVertices).
  bool joinIdenticalVertices = false;
};

/// What a file's material gives a visual model.
struct AssimpMaterial {
  std::string name;
  std::optional<Vec4d> diffuse;  ///< r g b a in [0, 1], when the file gives one
  std::optional<Vec4d> ambient;
  std::optional<Vec4d> specular;
  std::optional<double> shininess;
  std::string texture;     ///< the diffuse texture's path (relative ones made absolute); or empty
  bool isDefault = false;  ///< assimp's stand-in for a file without materials (or unnamed)
};

struct AssimpMesh {
  std::string name;  ///< the mesh's name in the file (may be empty)
  std::string node;  ///< the name of the node that places it
  MeshData mesh;     ///< positions, edges, triangles, quads, normals and texcoords
  unsigned material = 0;
  unsigned fileIndex = 0;  ///< its index among the file's meshes
};

struct AssimpFile {
  std::vector<AssimpMesh> meshes;  ///< one per placement, in the order of a depth-first walk
  std::vector<AssimpMaterial> materials;
  std::vector<std::string> meshNames;  ///< the file's meshes, by index
  std::vector<std::string> warnings;
};

/// Reads `path` with assimp. On failure returns false and sets `error` to assimp's reason
/// (or why the scene cannot be used: no mesh, an index out of range).
bool readAssimpFile(const std::string& path, const AssimpReadOptions& options, AssimpFile& file,
                    std::string& error);

/// The meshes one after the other in one MeshData (indices shifted). Normals and texture
/// coordinates are kept when at least one mesh has them; the others get zeros then.
MeshData mergeMeshes(const std::vector<const AssimpMesh*>& meshes);

}  // namespace stroma
