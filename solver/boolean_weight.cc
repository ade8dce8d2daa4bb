#include "solver/boolean_weight.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry.h"
#include "ops/extrude.h"

namespace opgraph {

namespace {

const ExtrudeOp& ExtrudeAt(const Sequence& sequence, int op) {
  const ExtrudeOp* extrude =
      op >= 0 && op < static_cast<int>(sequence.ops.size()) ? dynamic_cast<const ExtrudeOp*>(sequence.ops[op].get()) : nullptr;
  if (extrude == nullptr) throw std::invalid_argument("Boolean weight: op " + std::to_string(op) + " is not an Extrude");
  return *extrude;
}

// The region's plane: its area-weighted unit normal (the extrusion direction) and the mean of
// its vertices, at the input positions.
void RegionPlane(const ExtrudeOp& extrude, const RegionCopy& group, const Positions<double>& in, Vec3d* normal,
                 Vec3d* origin) {
  Vec3d n = Vec3d::Zero();
  for (int f : group.faces) n += FaceAreaNormal(in, extrude.input_faces()[f]);
  *normal = SafeNormalized(n);
  Vec3d o = Vec3d::Zero();
  for (const auto& [target, source] : group.caps) o += in[source];
  *origin = o / static_cast<double>(group.caps.size());
}

}  // namespace

VirtualSurface BooleanSurface(const Program& program, int op) {
  const ExtrudeOp& extrude = ExtrudeAt(program.sequence(), op);
  const Positions<double>& out = program.positions();
  const Positions<double>& in = program.InputPositions(op);
  VirtualSurface surface;
  surface.positions = out;
  surface.base.resize(out.size());
  for (size_t v = 0; v < out.size(); ++v) surface.base[v] = static_cast<int>(v);
  surface.offset.assign(out.size(), Vec3d::Zero());
  auto add_point = [&](int base, const Vec3d& offset) {
    surface.positions.push_back(out[base] + offset);
    surface.base.push_back(base);
    surface.offset.push_back(offset);
    return static_cast<int>(surface.positions.size()) - 1;
  };
  const std::vector<Polygon>& faces = program.faces();
  const int first_created = extrude.first_created_face();
  std::vector<Polygon> polygons(faces.begin(), faces.begin() + first_created);  // the untouched input faces
  const bool inward = program.Gate(op) * extrude.params()[0] < 0;
  int next_face = first_created;  // per set: its cap faces, then its side quads
  for (const RegionCopy& group : extrude.regions()) {
    Vec3d normal, origin;
    RegionPlane(extrude, group, in, &normal, &origin);
    const int num_caps = static_cast<int>(group.faces.size());
    std::vector<int> cap_of(in.size(), -1);
    for (const auto& [target, source] : group.caps) cap_of[source] = target;
    if (inward) {
      for (int f = next_face; f < next_face + num_caps; ++f) polygons.push_back(faces[f]);  // the prism's floor
      for (const RegionCopy::BoundaryEdge& edge : group.boundary) {
        // The cap's boundary edge a'b' and its projection onto the region's plane: a wall of the
        // prism, and the rim quad that is left of the region's face between the region's
        // boundary edge ab (kept at its input position) and the prism's top edge.
        const int a = cap_of[edge.a], b = cap_of[edge.b];
        const int a_top = add_point(a, -((out[a] - origin).dot(normal)) * normal);
        const int b_top = add_point(b, -((out[b] - origin).dot(normal)) * normal);
        polygons.push_back({a, b, b_top, a_top});
        polygons.push_back({edge.a, edge.b, b_top, a_top});
      }
    } else {
      // The prism is outside the solid: B is the input surface, the region's faces at their
      // input positions (a boundary vertex kept its input position, its cap copy is new; an
      // interior vertex moved with the cap).
      for (int f : group.faces) {
        Polygon polygon = extrude.input_faces()[f];
        for (int& v : polygon) {
          const int target = cap_of[v];
          v = target != v ? v : add_point(v, in[v] - out[v]);
        }
        polygons.push_back(polygon);
      }
    }
    next_face += num_caps + static_cast<int>(group.boundary.size());
  }
  surface.first_own_face = first_created;
  surface.triangles = FanTriangulate(polygons);
  return surface;
}

SurfaceCorrespondence CorrespondenceOnSurface(const VirtualSurface& surface, int triangle, const Vec3d& barycentric,
                                              const Vec3d& target_point, const Vec3d& target_normal) {
  SurfaceCorrespondence c;
  const MeshTriangle& t = surface.triangles[triangle];
  c.offset = Vec3d::Zero();
  for (int k = 0; k < 3; ++k) {
    c.vertices[k] = surface.base[t.v[k]];
    c.weights[k] = barycentric[k];
    c.offset += barycentric[k] * surface.offset[t.v[k]];
  }
  c.target_point = target_point;
  c.target_normal = target_normal;
  return c;
}

Json ExtrudeToBoolean(const Sequence& sequence, int op) {
  const Json document = SequenceToJson(sequence);
  Sequence copy = ParseSequence(document);
  copy.gates = sequence.gates;
  const std::vector<Mesh> steps = EvaluateSequence(&copy);
  const ExtrudeOp& extrude = ExtrudeAt(copy, op);
  const std::string label = "Boolean weight: Extrude at op " + std::to_string(op);
  if (!(copy.gates[op] * extrude.params()[0] < 0)) throw std::invalid_argument(label + " is not inward (height >= 0)");
  const Positions<double>& in = op == 0 ? copy.StartMesh().vertices : steps[op - 1].vertices;
  const Positions<double>& out = steps[op].vertices;
  Json booleans = Json::array();
  for (const RegionCopy& group : extrude.regions()) {
    Vec3d n, origin;
    RegionPlane(extrude, group, in, &n, &origin);
    std::vector<int> cap_of(in.size(), -1);
    for (const auto& [target, source] : group.caps) cap_of[source] = target;
    const RegionCopy::BoundaryEdge& first = group.boundary.front();
    Vec3d u = out[cap_of[first.b]] - out[cap_of[first.a]];
    u = SafeNormalized<double>(u - u.dot(n) * n);
    if (u.squaredNorm() == 0) throw std::invalid_argument(label + ": degenerate cap");
    // A centred cap's corners lie on the region face's diagonals, where the exact Boolean's
    // topology pass fails on the tie (a cube edge through an edge of the face's
    // triangulation); a turn of 0.01 degree about n (corners move by < 2e-4 of the cap's
    // size) breaks it.
    const double turn = DegToRad(0.01);
    u = std::cos(turn) * u + std::sin(turn) * n.cross(u);
    const Vec3d w = n.cross(u);
    Vec3d lower = Vec3d::Constant(1e300), upper = Vec3d::Constant(-1e300);
    for (const auto& [target, source] : group.caps) {
      const Vec3d d = out[target] - origin;
      const Vec3d local(d.dot(u), d.dot(w), d.dot(n));
      lower = lower.cwiseMin(local);
      upper = upper.cwiseMax(local);
    }
    const double depth = -lower[2];
    if (!(depth > 0)) throw std::invalid_argument(label + ": the cap does not go below the region's plane");
    lower[2] = std::min(lower[2], 0.0);
    upper[2] = std::max(upper[2], 0.0) + 0.1 * depth;
    const Vec3d centre_local = (lower + upper) / 2;
    const Vec3d location = origin + centre_local[0] * u + centre_local[1] * w + centre_local[2] * n;
    // Rotation [u w n] (the cube's X, Y, Z) as XYZ Euler angles, R = Rz Ry Rx.
    Eigen::Matrix3d r;
    r.col(0) = u, r.col(1) = w, r.col(2) = n;
    const double sin_y = std::max(-1.0, std::min(1.0, -r(2, 0)));
    double rx, ry = std::asin(sin_y), rz;
    if (std::abs(sin_y) < 1 - 1e-9) {
      rx = std::atan2(r(2, 1), r(2, 2));
      rz = std::atan2(r(1, 0), r(0, 0));
    } else {  // gimbal lock: only rz - rx (or rz + rx) is determined
      rx = 0;
      rz = std::atan2(-r(0, 1), r(1, 1));
    }
    booleans.push_back({{"op", "Boolean"},
                        {"params",
                         {{"operation", "DIFFERENCE"},
                          {"primitive", "cube"},
                          {"size", ToJson(upper - lower)},
                          {"rotation_deg", ToJson(Vec3d(rx, ry, rz) * (180.0 / kPi))},
                          {"location", ToJson(location)}}}});
  }
  Json converted = document;
  Json& operations = converted["operations"];
  operations.erase(op);
  operations.insert(operations.begin() + op, booleans.begin(), booleans.end());
  return converted;
}

}  // namespace opgraph
