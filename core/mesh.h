// Polygon meshes: a topology (faces as vertex-index loops) plus positions of any scalar type T,
// so the same topology carries double positions for the discrete passes and ceres::Jet positions
// for differentiation.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace opgraph {

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
using Vec3d = Vec3<double>;

// One face: vertex indices in counter-clockwise order seen from outside (Blender's winding).
using Polygon = std::vector<int>;

// #V positions.
template <typename T>
using Positions = std::vector<Vec3<T>>;

struct Mesh {
  Positions<double> vertices;   // #V
  std::vector<Polygon> faces;   // #F loops of indices into vertices

  int NumVertices() const { return static_cast<int>(vertices.size()); }
  int NumFaces() const { return static_cast<int>(faces.size()); }
  int NumEdges() const;
  // Empty when valid, else a one-line description (index out of range, face with < 3 vertices,
  // non-finite coordinate).
  std::string Validate() const;
};

// Blender's default cube (bmesh.ops.create_cube): side `size`, centred at the origin, with
// Blender's vertex and face order.
Mesh MakeCube(double size);

// Undirected edge key for maps.
inline long long EdgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<long long>(a) << 32) | static_cast<unsigned int>(b);
}

}  // namespace opgraph
