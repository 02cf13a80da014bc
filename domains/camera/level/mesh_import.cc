#include "sightline/domains/camera/level/mesh_import.h"

#include <assimp/commonMetaData.h>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace sightline::camera {
namespace {

csp::SourceLocation error_location(const LevelSpec& spec) {
  if (!spec.where.file.empty()) return spec.where;
  return csp::SourceLocation{spec.file, 0, 0};
}

[[noreturn]] void fail(const LevelSpec& spec, const std::string& message) {
  throw csp::InputError(error_location(spec), "level file '" + spec.file + "' " + message);
}

std::string mesh_name(const aiMesh& mesh, unsigned index) {
  if (mesh.mName.length > 0) return "mesh '" + std::string(mesh.mName.C_Str()) + "'";
  return "mesh " + std::to_string(index);
}

std::string node_name(const aiNode& node) {
  if (node.mName.length > 0) return "node '" + std::string(node.mName.C_Str()) + "'";
  return "an unnamed node";
}

bool is_finite(const aiVector3D& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// assimp's vertices as the file has them, before any post-processing: joining identical
// vertices compares coordinates, and with a NaN among them it may merge the NaN into a
// finite vertex or a finite vertex into the NaN, hiding which vertex was bad (or that one
// was). So the check names the mesh and the vertex as the file numbers them.
void check_vertices_finite(const LevelSpec& spec, const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      if (is_finite(p)) continue;
      std::ostringstream message;
      message << "has a vertex that is not a finite number: " << mesh_name(mesh, m) << ", vertex "
              << v << " of " << mesh.mNumVertices << ", is (" << p.x << ", " << p.y << ", " << p.z
              << ")";
      fail(spec, message.str());
    }
  }
}

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  // aiMatrix4x4 is row-major and transforms column vectors (translation in a4, b4, c4).
  for (unsigned r = 0; r < 4; ++r) {
    for (unsigned c = 0; c < 4; ++c) out(r, c) = m[r][c];
  }
  return out;
}

// For people: assimp's own name for the reader it used ("glTF2 Importer" -> "glTF2"), with
// the format version where the reader records one, else the name of the reader registered
// for the extension, else the extension.
std::string reader_name(const Assimp::Importer& importer, const aiScene& scene,
                        const std::string& file) {
  std::string name;
  std::string version;
  if (scene.mMetaData != nullptr) {
    aiString text;
    if (scene.mMetaData->Get(AI_METADATA_SOURCE_FORMAT, text)) name = text.C_Str();
    if (scene.mMetaData->Get(AI_METADATA_SOURCE_FORMAT_VERSION, text)) version = text.C_Str();
  }
  const std::string extension = std::filesystem::path(file).extension().string();
  if (name.empty() && !extension.empty()) {
    const std::size_t index = importer.GetImporterIndex(extension.c_str());
    if (index != static_cast<std::size_t>(-1)) {
      const aiImporterDesc* description = importer.GetImporterInfo(index);
      if (description != nullptr && description->mName != nullptr) name = description->mName;
    }
  }
  const std::string suffix = " Importer";
  if (name.size() > suffix.size() &&
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
    name.resize(name.size() - suffix.size());
  }
  if (name.empty()) name = extension.empty() ? std::string("unknown format") : extension;
  if (!version.empty()) name += " version " + version;
  return name;
}

// Every triangle of every mesh of every node, each through its node's global transform
// (the product of its ancestors' and its own), then `transform`. A mesh that two nodes
// reference is added twice, once per placement. An explicit stack, not recursion: a
// file's node depth is the file's to choose.
TriangleMesh collect_triangles(const LevelSpec& spec, const aiScene& scene,
                               const LevelTransform& transform) {
  TriangleMesh out;
  std::size_t skipped_primitives = 0;
  if (scene.mRootNode == nullptr) fail(spec, "has no node tree (assimp read no scene)");
  std::vector<std::pair<const aiNode*, Eigen::Matrix4d>> pending;
  pending.emplace_back(scene.mRootNode, Eigen::Matrix4d::Identity());
  while (!pending.empty()) {
    const auto [node, parent] = pending.back();
    pending.pop_back();
    const Eigen::Matrix4d global = parent * to_eigen(node->mTransformation);
    if (!global.allFinite()) {
      fail(spec, "has " + node_name(*node) + " whose transform is not finite");
    }
    // A mirroring transform (negative determinant) turns counter-clockwise corners
    // clockwise; swapping two corners keeps the front the side the file meant (glTF 2.0
    // asks for exactly this). Both sides block sight either way.
    const bool mirrored = global.topLeftCorner<3, 3>().determinant() < 0;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      if (node->mMeshes[i] >= scene.mNumMeshes) {
        fail(spec, "is corrupt: " + node_name(*node) + " refers to mesh " +
                       std::to_string(node->mMeshes[i]) + " of " +
                       std::to_string(scene.mNumMeshes));
      }
      const aiMesh& mesh = *scene.mMeshes[node->mMeshes[i]];
      // Points and lines block nothing; after aiProcess_SortByPType a mesh holds one kind.
      if ((mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) {
        skipped_primitives += mesh.mNumFaces;
        continue;
      }
      if (out.vertices.size() + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max()) {
        fail(spec, "has more than 2^32 vertices once its meshes are placed");
      }
      const auto offset = static_cast<std::uint32_t>(out.vertices.size());
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        const Eigen::Vector3d placed = (global * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>();
        out.vertices.push_back(transform.to_scene(placed).cast<float>());
      }
      for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;
        const std::uint32_t a = offset + face.mIndices[0];
        const std::uint32_t b = offset + face.mIndices[1];
        const std::uint32_t c = offset + face.mIndices[2];
        out.triangles.push_back(mirrored ? std::array<std::uint32_t, 3>{a, c, b}
                                         : std::array<std::uint32_t, 3>{a, b, c});
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      pending.emplace_back(node->mChildren[c], global);
  }
  if (out.empty() && skipped_primitives > 0) {
    fail(spec, "has no solid triangles, only " + std::to_string(skipped_primitives) +
                   " points and lines, which block nothing");
  }
  return out;
}

}  // namespace

Level load_mesh_level(const LevelSpec& spec, const LevelTransform& transform) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(spec.file, 0);
  if (scene == nullptr)
    fail(spec, std::string("could not be read by assimp: ") + importer.GetErrorString());
  // A file that parses but holds no mesh (comments only, a scene of cameras) is said so
  // here: assimp's validation would call it "aiScene::mNumMeshes is 0".
  if (scene->mNumMeshes == 0) {
    fail(spec, "holds no mesh, so no solid triangles (read by assimp as " +
                   reader_name(importer, *scene, spec.file) + ")");
  }
  // Vertices without faces (a point cloud): validation would call it "Mesh contains no faces".
  std::size_t faces = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) faces += scene->mMeshes[m]->mNumFaces;
  if (faces == 0) fail(spec, "has no solid triangles: its meshes hold vertices but no faces");
  // Validated before anything reads it (indices in range, a node tree, ...), so nothing
  // below reads past an array; the other post-processing comes after the NaN check.
  scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
  if (scene == nullptr)
    fail(spec, std::string("is not valid for assimp: ") + importer.GetErrorString());
  check_vertices_finite(spec, *scene);
  // Triangulate: polygons (quads, n-gons) become triangles. JoinIdenticalVertices: an
  // indexed mesh, not three vertices per triangle. SortByPType: one primitive kind per
  // mesh, so points and lines are skipped whole. Node transforms are applied below in
  // double precision, in the same pass as scale and up, rather than by
  // aiProcess_PreTransformVertices (which bakes them in float and rewrites the node tree).
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                       aiProcess_SortByPType);
  if (scene == nullptr) {
    fail(spec, std::string("could not be processed by assimp: ") + importer.GetErrorString());
  }

  Level level;
  level.file = spec.file;
  level.format = reader_name(importer, *scene, spec.file) + " (assimp)";
  level.transform = transform;
  level.mesh = collect_triangles(spec, *scene, transform);
  return level;
}

}  // namespace sightline::camera
