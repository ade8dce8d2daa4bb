#include "io/blender_import_frame.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace opgraph {

Eigen::Matrix3d BlenderImportFrame(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Eigen::Matrix3d blender_from_file = Eigen::Matrix3d::Identity();
  if (extension == ".obj" || extension == ".gltf" || extension == ".glb") {
    blender_from_file << 1, 0, 0,  //
        0, 0, -1,                  //
        0, 1, 0;
  }
  return blender_from_file;
}

}  // namespace opgraph
