// Where Blender's default importer puts a file's coordinates, so a rebuilt object can sit on the
// imported source.
#pragma once

#include <Eigen/Core>
#include <string>

namespace opgraph {

// Blender's world from the file's coordinates under Blender 3.4's default importer for the
// format of `path` (by its extension): OBJ (forward -Z, up Y) and glTF (+Y up) turn Y-up into
// Z-up, (x, y, z) -> (x, -z, y); PLY and STL are imported as they are. Formats Blender has no
// default importer for (OFF, PCD, XYZ) or whose axes the file itself declares (FBX, Collada) get
// the identity.
Eigen::Matrix3d BlenderImportFrame(const std::string& path);

}  // namespace opgraph
