// Reading a user's input geometry: a polygon mesh or a point cloud, in the file's own frame and
// units (nothing is normalised here; the fitter normalises and maps results back).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

struct InputGeometry {
  // Vertices and polygons (faces empty for a point cloud). Several parts are concatenated;
  // vertices at exactly equal positions are welded.
  Mesh mesh;
  // #V unit normals when the file carries them (point clouds), else empty.
  Positions<double> normals;

  bool IsPointCloud() const { return mesh.faces.empty(); }
};

// Reads meshes in every format Assimp knows (OBJ, PLY, STL, OFF, glTF/GLB, FBX, ...), keeping
// polygons and applying the scene's node transforms, and point clouds: PCD (PCL), XYZ text
// (`x y z [nx ny nz]` per line; also .pts/.txt), and PLY files without faces.
// Throws std::runtime_error with a one-line message naming the problem (missing, empty or
// corrupt file, unsupported format, non-finite coordinates, zero extent). Assimp and PCL read in
// a forked child process (io/read_in_child_process.h), so a file that crashes them is an error
// here too.
// Global state: a host program's PCL verbosity and Assimp DefaultLogger are as they were after
// the call (test: ReadInput.LeavesTheHostsLoggingAsItWas). Calls on several threads are safe
// (Assimp reads are serialised on its global logger); while one runs, PCL's process-wide
// verbosity is lowered, so a host's own PCL messages on another thread may be silenced then.
InputGeometry ReadInput(const std::string& path);

// Estimates unit normals of a point cloud from its `k` nearest neighbours (PCL), oriented
// consistently over the surface and outwards (io/orient_normals.h); away from the cloud's
// centroid where that cannot reach. `points`: #P positions. Returns #P normals.
Positions<double> EstimatePointNormals(const Positions<double>& points, int k = 16);

}  // namespace opgraph
