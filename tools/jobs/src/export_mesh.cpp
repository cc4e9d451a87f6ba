#include "cordgrasp/jobs/export_mesh.h"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <stdexcept>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/jobs/hand_scene.h"

namespace cordgrasp {
namespace {

/// An assimp mesh of `mesh` placed by X_OM (vertices in the object frame), smooth normals
/// left to the reader; material `material`.
aiMesh* make_ai_mesh(const Mesh& mesh, const Eigen::Isometry3d& X_OM, const std::string& name,
                     unsigned material) {
  auto* m = new aiMesh();
  m->mName = aiString(name);
  m->mMaterialIndex = material;
  m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  m->mNumVertices = static_cast<unsigned>(mesh.vertices.size());
  m->mVertices = new aiVector3D[m->mNumVertices];
  for (unsigned i = 0; i < m->mNumVertices; ++i) {
    const Eigen::Vector3d p = X_OM * mesh.vertices[i];
    m->mVertices[i] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()),
                                 static_cast<ai_real>(p.z()));
  }
  m->mNumFaces = static_cast<unsigned>(mesh.triangles.size());
  m->mFaces = new aiFace[m->mNumFaces];
  for (unsigned f = 0; f < m->mNumFaces; ++f) {
    aiFace& face = m->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    for (int c = 0; c < 3; ++c) face.mIndices[c] = static_cast<unsigned>(mesh.triangles[f][c]);
  }
  return m;
}

aiMaterial* make_material(const Eigen::Vector4d& rgba, const std::string& name) {
  auto* mat = new aiMaterial();
  const aiString n(name);
  mat->AddProperty(&n, AI_MATKEY_NAME);
  const aiColor4D c(static_cast<float>(rgba[0]), static_cast<float>(rgba[1]),
                    static_cast<float>(rgba[2]), static_cast<float>(rgba[3]));
  mat->AddProperty(&c, 1, AI_MATKEY_COLOR_DIFFUSE);
  mat->AddProperty(&c, 1, AI_MATKEY_BASE_COLOR);
  return mat;
}

}  // namespace

void write_grasp_mesh(const std::string& path, const std::string& format_id,
                      const HandModel& hand, const Grasp& grasp, const Mesh& object) {
  if (format_id != "glb2" && format_id != "obj")
    throw std::invalid_argument("write_grasp_mesh: format '" + format_id +
                                "' is not glb2 or obj");
  const std::vector<Eigen::Isometry3d> X_OL =
      link_poses(hand, apply_couplings(hand, grasp.q), grasp.X_OB);
  const HandMeshes meshes = make_hand_meshes(hand);

  std::vector<aiMesh*> ai_meshes;
  std::vector<aiMaterial*> materials;
  ai_meshes.push_back(make_ai_mesh(object, Eigen::Isometry3d::Identity(), "object", 0));
  materials.push_back(make_material(object_color(), "object"));
  for (size_t i = 0; i < meshes.parts.size(); ++i) {
    const HandMeshes::Part& part = meshes.parts[i];
    const std::string name = hand.links[part.link].name + "_" + std::to_string(i);
    const unsigned material = static_cast<unsigned>(materials.size());
    materials.push_back(make_material(part.rgba, name));
    ai_meshes.push_back(make_ai_mesh(*part.mesh, X_OL[part.link] * part.X_LG, name, material));
  }

  aiScene scene;  // owns everything below; its destructor frees it
  scene.mRootNode = new aiNode("grasp");
  scene.mNumMeshes = static_cast<unsigned>(ai_meshes.size());
  scene.mMeshes = new aiMesh*[scene.mNumMeshes];
  scene.mRootNode->mNumMeshes = scene.mNumMeshes;
  scene.mRootNode->mMeshes = new unsigned[scene.mNumMeshes];
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    scene.mMeshes[i] = ai_meshes[i];
    scene.mRootNode->mMeshes[i] = i;
  }
  scene.mNumMaterials = static_cast<unsigned>(materials.size());
  scene.mMaterials = new aiMaterial*[scene.mNumMaterials];
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) scene.mMaterials[i] = materials[i];

  Assimp::Exporter exporter;
  if (exporter.Export(&scene, format_id, path) != AI_SUCCESS)
    throw InputError("export: '" + path + "': " + exporter.GetErrorString());
}

}  // namespace cordgrasp
