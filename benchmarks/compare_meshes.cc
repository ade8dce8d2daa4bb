// Prints how far two OBJ meshes are apart: the symmetric point-to-surface distance relative to
// the first one's bounding-box diagonal, and both vertex and face counts (the Blender replay
// check of the tests, for one pair by hand).  Usage: build/compare_meshes A.obj B.obj
#include <iostream>

#include "apps/cli_flags.h"
#include "core/obj_io.h"
#include "core/surface_distance.h"

int main(int argc, char** argv) {
  constexpr const char* kUsage = "usage: compare_meshes A.obj B.obj";
  const std::vector<std::string> meshes =
      opgraph::ParseCommandLineOrExit(argc, argv, {"compare_meshes", kUsage, /*flags_file=*/"", /*max_arguments=*/2});
  if (meshes.size() != 2) return opgraph::BadInput("compare_meshes", std::string(kUsage) + " (see --help)");
  try {
    const opgraph::Mesh a = opgraph::ReadObj(meshes[0]), b = opgraph::ReadObj(meshes[1]);
    std::cout << "distance " << opgraph::SymmetricSurfaceDistanceRelative(a, b) << " of the diagonal; vertices "
              << a.NumVertices() << " vs " << b.NumVertices() << ", faces " << a.NumFaces() << " vs " << b.NumFaces()
              << "\n";
  } catch (const std::exception& e) {
    return opgraph::BadInput("compare_meshes", e.what());
  }
  return 0;
}
