#include "ops/loop_cut.h"

#include <cmath>
#include <deque>
#include <limits>

#include "ops/halfedge_topology.h"

namespace opgraph {

namespace {
const std::vector<std::string> kAxes = {"X", "Y", "Z"};
}  // namespace

LoopCutOp::LoopCutOp(const Json& params) {
  ParamReader reader(params);
  axis_ = reader.Word("axis", kAxes)[0] - 'X';
  cuts_ = reader.Integer("cuts", 1, 64);
  near_ = reader.Vector3("near", -1e6, 1e6, Vec3d::Zero());
  reader.Finish();
}

namespace {

// The seed edge (see loop_cut.h): the axis-parallel edge whose midpoint is nearest to `near`.
// Ties (a `near` point midway between two rings) are broken by position, not by edge order,
// which differs in Blender: within `tie`, the midpoint with the smallest x, then y, then z.
int SeedEdge(const Mesh& input, const HalfedgeTopology& topology, const std::vector<bool>& parallel,
             const Vec3d& near) {
  const auto& v = input.vertices;
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Vec3d& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tie = kLoopCutTie * (hi - lo).norm();
  auto midpoint = [&](int e) -> Vec3d {
    const auto [a, b] = topology.EdgeVertices(e);
    return 0.5 * (v[a] + v[b]);
  };
  double best = std::numeric_limits<double>::infinity();
  for (int e = 0; e < topology.NumEdges(); ++e) {
    if (parallel[e]) best = std::min(best, (midpoint(e) - near).norm());
  }
  auto before = [&](const Vec3d& a, const Vec3d& b) {
    for (int k = 0; k < 3; ++k) {
      if (a[k] < b[k] - tie) return true;
      if (a[k] > b[k] + tie) return false;
    }
    return false;
  };
  int seed = -1;
  for (int e = 0; e < topology.NumEdges(); ++e) {
    if (!parallel[e] || (midpoint(e) - near).norm() > best + tie) continue;
    if (seed < 0 || before(midpoint(e), midpoint(seed))) seed = e;
  }
  return seed;
}

// The ring from `seed`: BFS across quads, propagating the orientation (an oriented edge's first
// vertex corresponds to the first vertex of the edge it was reached from). *ring_of_edge gets
// each edge's index in the ring, or -1.
std::vector<std::pair<int, int>> GrowRing(const Mesh& input, const HalfedgeTopology& topology,
                                          const std::vector<bool>& parallel, int seed,
                                          std::vector<int>* ring_of_edge) {
  std::vector<std::pair<int, int>> ring = {topology.EdgeVertices(seed)};
  ring_of_edge->assign(topology.NumEdges(), -1);
  (*ring_of_edge)[seed] = 0;
  std::deque<int> queue = {seed};
  while (!queue.empty()) {
    const int e = queue.front();
    queue.pop_front();
    const auto oriented = ring[(*ring_of_edge)[e]];
    for (const HalfedgeTopology::Corner& corner : topology.EdgeCorners(e)) {
      const Polygon& q = input.faces[corner.face];
      if (q.size() != 4) continue;
      int i = 0;  // the quad's first corner on e
      while (topology.CornerEdge(corner.face, i) != e) ++i;
      const HalfedgeTopology::Corner across = HalfedgeTopology::AcrossQuad({corner.face, i});
      const int c = q[across.corner], d = q[(across.corner + 1) % 4];  // d adjacent to q[i]
      const int o = topology.CornerEdge(across.face, across.corner);
      if ((*ring_of_edge)[o] >= 0 || !parallel[o]) continue;
      (*ring_of_edge)[o] = static_cast<int>(ring.size());
      ring.push_back(oriented.first == q[i] ? std::make_pair(d, c) : std::make_pair(c, d));
      queue.push_back(o);
    }
  }
  return ring;
}

}  // namespace

void LoopCutOp::Prepare(const Mesh& input) {
  num_input_vertices_ = input.NumVertices();
  const auto& v = input.vertices;
  const auto topology = HalfedgeTopology::Of(input);
  std::vector<bool> parallel(topology->NumEdges());
  for (int e = 0; e < topology->NumEdges(); ++e) {
    const auto [a, b] = topology->EdgeVertices(e);
    const Vec3d d = v[b] - v[a];
    const double length = d.norm();
    parallel[e] = length > 0 && std::abs(d[axis_]) >= 0.95 * length;
  }
  const int seed = SeedEdge(input, *topology, parallel, near_);
  if (seed < 0) throw FieldError("near", "no edge parallel to the axis " + kAxes[axis_]);
  std::vector<int> ring_of_edge;
  ring_ = GrowRing(input, *topology, parallel, seed, &ring_of_edge);
  // A face the ring crosses has two of its edges, so it splits into at most cuts + 1 faces.
  CheckOutputFaces("cuts", static_cast<int64_t>(input.faces.size()) + static_cast<int64_t>(ring_.size()) * cuts_);

  // Cut vertex k (1..cuts) along corner i of face f.
  auto cut = [&](int f, int i, int k) {
    const int r = ring_of_edge[topology->CornerEdge(f, i)];
    const int base = num_input_vertices_ + r * cuts_ - 1;
    return ring_[r].first == input.faces[f][i] ? base + k : base + cuts_ + 1 - k;
  };
  auto in_ring = [&](int f, int i) { return ring_of_edge[topology->CornerEdge(f, i)] >= 0; };

  output_faces_.clear();
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    const int n = static_cast<int>(face.size());
    int count = 0;
    for (int i = 0; i < n; ++i) count += in_ring(f, i);
    if (count == 0) {
      output_faces_.push_back(face);
      continue;
    }
    if (n == 4 && count == 2) {
      int i = 0;
      while (!in_ring(f, i)) ++i;
      const int j = (i + 2) % 4;
      if (in_ring(f, j)) {
        // Corner j runs p2 -> p3; its cuts counted from p3 match corner i's from p0.
        const int p0 = face[i], p1 = face[(i + 1) % 4], p2 = face[j], p3 = face[(i + 3) % 4];
        auto side_a = [&](int k) { return k == 0 ? p0 : k == cuts_ + 1 ? p1 : cut(f, i, k); };
        auto side_b = [&](int k) { return k == 0 ? p3 : k == cuts_ + 1 ? p2 : cut(f, j, cuts_ + 1 - k); };
        for (int k = 0; k <= cuts_; ++k) {
          output_faces_.push_back({side_a(k), side_a(k + 1), side_b(k + 1), side_b(k)});
        }
        continue;
      }
    }
    Polygon loop;
    for (int i = 0; i < n; ++i) {
      loop.push_back(face[i]);
      if (in_ring(f, i)) {
        for (int k = 1; k <= cuts_; ++k) loop.push_back(cut(f, i, k));
      }
    }
    output_faces_.push_back(loop);
  }
  num_output_vertices_ = num_input_vertices_ + static_cast<int>(ring_.size()) * cuts_;
}

template <typename T>
void LoopCutOp::Apply(const T* /*p*/, const T& /*gate*/, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  out->reserve(in.size() + ring_.size() * cuts_);
  for (const auto& edge : ring_) {
    const Vec3<T>& a = in[edge.first];
    const Vec3<T>& b = in[edge.second];
    for (int k = 1; k <= cuts_; ++k) {
      const double t = static_cast<double>(k) / (cuts_ + 1);
      out->push_back(a + (b - a) * T(t));
    }
  }
}

template void LoopCutOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                       Positions<double>*) const;
template void LoopCutOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                     Positions<JetT>*) const;

Json LoopCutOp::ParamsToJson() const {
  return {{"axis", kAxes[axis_]}, {"cuts", cuts_}, {"near", ToJson(near_)}};
}

std::string LoopCutOp::BlenderCode() const {
  Vec3d axis = Vec3d::Zero();
  axis[axis_] = 1;
  return "kLoopCutTie = " + Py(kLoopCutTie) + "\n" + std::string(R"PY(def opgraph_edge_ring(bm, axis, near):
    def parallel(e):
        d = e.verts[1].co - e.verts[0].co
        return d.length > 0 and abs(d.dot(axis)) >= 0.95 * d.length
    candidates = [e for e in bm.edges if parallel(e)]
    if not candidates:
        raise RuntimeError('LoopCut: no edge parallel to the axis')
    def mid(e):
        return (e.verts[0].co + e.verts[1].co) * 0.5
    lo = Vector([min(v.co[k] for v in bm.verts) for k in range(3)])
    hi = Vector([max(v.co[k] for v in bm.verts) for k in range(3)])
    tie = kLoopCutTie * (hi - lo).length
    best = min((mid(e) - near).length for e in candidates)
    def before(a, b):
        for k in range(3):
            if a[k] < b[k] - tie:
                return True
            if a[k] > b[k] + tie:
                return False
        return False
    seed = None
    for e in candidates:
        if (mid(e) - near).length <= best + tie and (seed is None or before(mid(e), mid(seed))):
            seed = e
    ring = [seed]
    seen = {seed}
    queue = [seed]
    while queue:
        e = queue.pop(0)
        for f in e.link_faces:
            if len(f.loops) != 4:
                continue
            loops = list(f.loops)
            i = [l.edge for l in loops].index(e)
            o = loops[(i + 2) % 4].edge
            if o not in seen and parallel(o):
                seen.add(o)
                ring.append(o)
                queue.append(o)
    return ring


me, bm = open_bmesh(obj)
)PY") + "ring = opgraph_edge_ring(bm, Vector(" + PyVec(axis) + "), Vector(" + PyVec(near_) + "))\n" +
         "bmesh.ops.subdivide_edges(bm, edges=ring, cuts=" + std::to_string(cuts_) +
         ", use_grid_fill=" + PyBool(true) + ")\n" +
         "close_bmesh(me, bm)\n";
}

}  // namespace opgraph
