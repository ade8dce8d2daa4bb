#include "io/write_glb.h"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <memory>
#include <stdexcept>

namespace opgraph {
namespace {

aiMesh* ToAssimp(const Mesh& mesh, const std::string& name) {
  auto* out = new aiMesh;
  out->mName = aiString(name);
  out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out->mMaterialIndex = 0;
  out->mNumVertices = static_cast<unsigned>(mesh.NumVertices());
  out->mVertices = new aiVector3D[out->mNumVertices];
  for (int v = 0; v < mesh.NumVertices(); ++v) {
    const Vec3d& p = mesh.vertices[v];
    out->mVertices[v] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
  }
  unsigned num_triangles = 0;
  for (const Polygon& f : mesh.faces) num_triangles += f.size() >= 3 ? static_cast<unsigned>(f.size() - 2) : 0;
  out->mNumFaces = num_triangles;
  out->mFaces = new aiFace[num_triangles];
  unsigned t = 0;
  for (const Polygon& f : mesh.faces) {
    for (size_t k = 1; k + 1 < f.size(); ++k, ++t) {
      out->mFaces[t].mNumIndices = 3;
      out->mFaces[t].mIndices = new unsigned[3]{static_cast<unsigned>(f[0]), static_cast<unsigned>(f[k]),
                                                static_cast<unsigned>(f[k + 1])};
    }
  }
  return out;
}

}  // namespace

std::string GlbBytes(const std::vector<Mesh>& meshes, const std::vector<std::string>& names) {
  if (meshes.size() != names.size()) throw std::invalid_argument("GlbBytes: one name per mesh");
  auto scene = std::make_unique<aiScene>();
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
  scene->mNumMeshes = static_cast<unsigned>(meshes.size());
  scene->mMeshes = new aiMesh*[meshes.size()];
  scene->mRootNode = new aiNode("opgraph");
  scene->mRootNode->mNumChildren = static_cast<unsigned>(meshes.size());
  scene->mRootNode->mChildren = new aiNode*[meshes.size()];
  for (size_t i = 0; i < meshes.size(); ++i) {
    scene->mMeshes[i] = ToAssimp(meshes[i], names[i]);
    aiNode* node = new aiNode(names[i]);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{static_cast<unsigned>(i)};
    scene->mRootNode->mChildren[i] = node;
  }
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), "glb2");
  if (blob == nullptr) throw std::runtime_error(std::string("glTF export failed: ") + exporter.GetErrorString());
  return std::string(static_cast<const char*>(blob->data), blob->size);
}

}  // namespace opgraph
