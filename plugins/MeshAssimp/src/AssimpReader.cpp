// SPDX-License-Identifier: MIT
#include "AssimpReader.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>

namespace stroma {
namespace {

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d result;
  result << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
      m.d3, m.d4;
  return result;
}

std::optional<Vec4d> color(const aiMaterial& material, const char* key, unsigned type,
                           unsigned index) {
  aiColor4D c;
  if (material.Get(key, type, index, c) != aiReturn_SUCCESS) return std::nullopt;
  return Vec4d(c.r, c.g, c.b, c.a);
}

AssimpMaterial readMaterial(const aiMaterial& material, const std::filesystem::path& folder,
                            std::vector<std::string>& warnings) {
  AssimpMaterial result;
  aiString name;
  if (material.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS) result.name = name.C_Str();
  // assimp's stand-in for a file without materials: 'DefaultMaterial', or unnamed (PLY).
  result.isDefault = result.name.empty() || result.name == AI_DEFAULT_MATERIAL_NAME;
  result.diffuse = color(material, AI_MATKEY_COLOR_DIFFUSE);
  if (!result.diffuse) result.diffuse = color(material, AI_MATKEY_BASE_COLOR);
  // OBJ's d and glTF's alpha both arrive as the opacity; OBJ's Kd has no alpha of its own.
  float opacity = 1;
  if (result.diffuse && material.Get(AI_MATKEY_OPACITY, opacity) == aiReturn_SUCCESS)
    (*result.diffuse)[3] = opacity;
  result.ambient = color(material, AI_MATKEY_COLOR_AMBIENT);
  result.specular = color(material, AI_MATKEY_COLOR_SPECULAR);
  float shininess = 0;
  if (material.Get(AI_MATKEY_SHININESS, shininess) == aiReturn_SUCCESS)
    result.shininess = shininess;

  aiString texture;
  if (material.GetTexture(aiTextureType_DIFFUSE, 0, &texture) != aiReturn_SUCCESS &&
      material.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) != aiReturn_SUCCESS)
    return result;
  const std::string path = texture.C_Str();
  if (!path.empty() && path[0] == '*') {
    warnings.push_back("material '" + result.name +
                       "': its texture is embedded in the file, which visual models cannot "
                       "read; it is left out");
    return result;
  }
  std::filesystem::path file(path);
  result.texture = (file.is_absolute() ? file : (folder / file).lexically_normal()).string();
  return result;
}

/// Copies one assimp mesh, placed by `transform`. False (with `error`) on an index out of range.
bool copyMesh(const aiMesh& source, const Eigen::Matrix4d& transform,
              const AssimpReadOptions& options, MeshData& mesh, std::string& error) {
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3>();
  const Eigen::Vector3d shift = transform.topRightCorner<3, 1>();
  const Eigen::Matrix3d normalMap = linear.inverse().transpose();
  mesh.positions.reserve(source.mNumVertices);
  for (unsigned i = 0; i < source.mNumVertices; ++i) {
    const aiVector3D& p = source.mVertices[i];
    mesh.positions.push_back(linear * Vec3d(p.x, p.y, p.z) + shift);
  }
  if (source.mNormals) {
    for (unsigned i = 0; i < source.mNumVertices; ++i) {
      const aiVector3D& n = source.mNormals[i];
      Vec3d mapped = normalMap * Vec3d(n.x, n.y, n.z);
      const double length = mapped.norm();
      // assimp leaves NaN (or zero) normals at points of degenerate faces only.
      mesh.normals.push_back(length > 0 && std::isfinite(length) ? Vec3d(mapped / length)
                                                                 : Vec3d::Zero());
    }
  }
  if (source.mTextureCoords[0]) {
    for (unsigned i = 0; i < source.mNumVertices; ++i)
      mesh.texcoords.emplace_back(source.mTextureCoords[0][i].x, source.mTextureCoords[0][i].y);
  }
  for (unsigned f = 0; f < source.mNumFaces; ++f) {
    const aiFace& face = source.mFaces[f];
    for (unsigned k = 0; k < face.mNumIndices; ++k)
      if (face.mIndices[k] >= source.mNumVertices) {
        error = "mesh '" + std::string(source.mName.C_Str()) + "', face " + std::to_string(f) +
                ": point index " + std::to_string(face.mIndices[k]) + " out of range (" +
                std::to_string(source.mNumVertices) + " points)";
        return false;
      }
    const auto at = [&](unsigned k) { return static_cast<Index>(face.mIndices[k]); };
    if (face.mNumIndices == 2)
      mesh.edges.push_back({at(0), at(1)});
    else if (face.mNumIndices == 3)
      mesh.triangles.push_back({at(0), at(1), at(2)});
    else if (face.mNumIndices == 4 && options.keepQuads)
      mesh.quads.push_back({at(0), at(1), at(2), at(3)});
    else  // only without aiProcess_Triangulate: a fan, as for a convex polygon
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k)
        mesh.triangles.push_back({at(0), at(k), at(k + 1)});
  }
  return true;
}

struct TreeWalk {
  const aiScene& scene;
  const AssimpReadOptions& options;
  AssimpFile& file;
  std::string& error;

  bool visit(const aiNode& node, const Eigen::Matrix4d& parent) {
    const Eigen::Matrix4d global = parent * toEigen(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      const unsigned index = node.mMeshes[i];
      if (index >= scene.mNumMeshes) {
        error = "node '" + std::string(node.mName.C_Str()) + "' names mesh " +
                std::to_string(index) + " of " + std::to_string(scene.mNumMeshes);
        return false;
      }
      const aiMesh& source = *scene.mMeshes[index];
      AssimpMesh placed;
      placed.name = source.mName.C_Str();
      placed.node = node.mName.C_Str();
      placed.material = source.mMaterialIndex;
      placed.fileIndex = index;
      if (!copyMesh(source, global, options, placed.mesh, error)) return false;
      file.meshes.push_back(std::move(placed));
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i)
      if (!visit(*node.mChildren[i], global)) return false;
    return true;
  }
};

}  // namespace

bool readAssimpFile(const std::string& path, const AssimpReadOptions& options, AssimpFile& file,
                    std::string& error) {
  file = {};
  Assimp::Importer importer;
  // Coordinates as the file writes them: assimp would turn a Collada Z_UP file to y up, which
  // would turn the meshes of a URDF robot (z up, as ROS) away from their links. Its unit is
  // still applied (points in meters).
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  unsigned flags = aiProcess_ValidateDataStructure | aiProcess_GenSmoothNormals;
  if (!options.keepQuads) flags |= aiProcess_Triangulate;
  if (options.joinIdenticalVertices) flags |= aiProcess_JoinIdenticalVertices;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene) {
    error = importer.GetErrorString();
    if (error.empty()) error = "assimp gave no scene and no reason";
    return false;
  }
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE || !scene->mRootNode || scene->mNumMeshes == 0) {
    error = "the file holds no mesh (an empty or incomplete scene)";
    return false;
  }
  for (unsigned i = 0; i < scene->mNumMeshes; ++i)
    file.meshNames.emplace_back(scene->mMeshes[i]->mName.C_Str());
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (unsigned i = 0; i < scene->mNumMaterials; ++i)
    file.materials.push_back(readMaterial(*scene->mMaterials[i], folder, file.warnings));
  TreeWalk walk{*scene, options, file, error};
  if (!walk.visit(*scene->mRootNode, Eigen::Matrix4d::Identity())) return false;
  if (file.meshes.empty()) {
    error = "no node of the file's tree places any of its " + std::to_string(scene->mNumMeshes) +
            " meshes";
    return false;
  }
  return true;
}

MeshData mergeMeshes(const std::vector<const AssimpMesh*>& meshes) {
  MeshData merged;
  bool normals = false;
  bool texcoords = false;
  for (const AssimpMesh* m : meshes) {
    normals = normals || !m->mesh.normals.empty();
    texcoords = texcoords || !m->mesh.texcoords.empty();
  }
  for (const AssimpMesh* m : meshes) {
    const MeshData& part = m->mesh;
    const auto offset = static_cast<Index>(merged.positions.size());
    merged.positions.insert(merged.positions.end(), part.positions.begin(), part.positions.end());
    const auto fill = [&](auto& into, const auto& from, const auto& zero) {
      if (from.empty())
        into.resize(merged.positions.size(), zero);
      else
        into.insert(into.end(), from.begin(), from.end());
    };
    if (normals) fill(merged.normals, part.normals, Vec3d::Zero().eval());
    if (texcoords) fill(merged.texcoords, part.texcoords, Vec2d::Zero().eval());
    for (Edge e : part.edges) merged.edges.push_back({e[0] + offset, e[1] + offset});
    for (Triangle t : part.triangles)
      merged.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    for (Quad q : part.quads)
      merged.quads.push_back({q[0] + offset, q[1] + offset, q[2] + offset, q[3] + offset});
  }
  return merged;
}

}  // namespace stroma
