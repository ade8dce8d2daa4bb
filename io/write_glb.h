// The steps of a sequence as one binary glTF 2.0 file (written by Assimp's exporter).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

// A .glb holding one node and one mesh per entry of `meshes`, named by `names` (same length),
// polygons fan-triangulated, coordinates as given (glTF is +Y up: a Y-up input's frame stays
// right). Returns the file's bytes; throws std::runtime_error when Assimp cannot export.
std::string GlbBytes(const std::vector<Mesh>& meshes, const std::vector<std::string>& names);

}  // namespace opgraph
