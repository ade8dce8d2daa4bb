// Wavefront OBJ reading and writing of polygon meshes (v and f records; polygons kept).
#pragma once

#include <string>

#include "core/mesh.h"

namespace opgraph {

// Reads `path`. Throws std::runtime_error with a one-line message naming the problem
// (missing file, empty mesh, malformed record, index out of range, non-finite value).
Mesh ReadObj(const std::string& path);

// Writes `mesh` to `path` atomically (temporary file, then rename). Throws on failure.
void WriteObj(const Mesh& mesh, const std::string& path, const std::string& comment = "");

// Writes `contents` to `path` atomically. Throws std::runtime_error on failure.
void WriteFileAtomic(const std::string& path, const std::string& contents);

}  // namespace opgraph
