// Prints how far two OBJ meshes are apart: the symmetric point-to-surface distance relative to
// the first one's bounding-box diagonal, and both vertex and face counts (the Blender replay
// check of the tests, for one pair by hand).  Usage: build/compare_meshes A.obj B.obj
#include <iostream>

#include "core/obj_io.h"
#include "core/surface_distance.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compare_meshes A.obj B.obj\n";
    return 2;
  }
  try {
    const opgraph::Mesh a = opgraph::ReadObj(argv[1]), b = opgraph::ReadObj(argv[2]);
    std::cout << "distance " << opgraph::SymmetricSurfaceDistanceRelative(a, b) << " of the diagonal; vertices "
              << a.NumVertices() << " vs " << b.NumVertices() << ", faces " << a.NumFaces() << " vs " << b.NumFaces()
              << "\n";
  } catch (const std::exception& e) {
    std::cerr << "compare_meshes: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
