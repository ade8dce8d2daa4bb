#include "ops/loop_cut.h"

#include <cmath>
#include <deque>
#include <limits>
#include <unordered_map>

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

void LoopCutOp::Prepare(const Mesh& input) {
  num_input_vertices_ = input.NumVertices();
  const auto& v = input.vertices;
  // Edges in order of first appearance, with their adjacent faces.
  std::vector<std::pair<int, int>> edges;
  std::vector<std::vector<int>> edge_faces;
  std::unordered_map<long long, int> edge_index;
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    for (size_t i = 0; i < face.size(); ++i) {
      const int a = face[i], b = face[(i + 1) % face.size()];
      auto it = edge_index.find(EdgeKey(a, b));
      if (it == edge_index.end()) {
        it = edge_index.emplace(EdgeKey(a, b), static_cast<int>(edges.size())).first;
        edges.push_back({a, b});
        edge_faces.emplace_back();
      }
      edge_faces[it->second].push_back(f);
    }
  }
  auto parallel = [&](int e) {
    const Vec3d d = v[edges[e].second] - v[edges[e].first];
    const double length = d.norm();
    return length > 0 && std::abs(d[axis_]) >= 0.95 * length;
  };
  // Ties (a `near` point midway between two rings) are broken by position, not by edge order,
  // which differs in Blender: within `tie`, the midpoint with the smallest x, then y, then z.
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Vec3d& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tie = kLoopCutTie * (hi - lo).norm();
  auto midpoint = [&](int e) -> Vec3d { return 0.5 * (v[edges[e].first] + v[edges[e].second]); };
  double best = std::numeric_limits<double>::infinity();
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    if (parallel(e)) best = std::min(best, (midpoint(e) - near_).norm());
  }
  auto before = [&](const Vec3d& a, const Vec3d& b) {
    for (int k = 0; k < 3; ++k) {
      if (a[k] < b[k] - tie) return true;
      if (a[k] > b[k] + tie) return false;
    }
    return false;
  };
  int seed = -1;
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    if (!parallel(e) || (midpoint(e) - near_).norm() > best + tie) continue;
    if (seed < 0 || before(midpoint(e), midpoint(seed))) seed = e;
  }
  if (seed < 0) throw FieldError("near", "no edge parallel to the axis " + kAxes[axis_]);

  // BFS across quads, propagating the orientation (a corresponds to the vertex adjacent to a).
  ring_.clear();
  std::unordered_map<long long, int> ring_index;
  std::deque<int> queue;
  ring_index[EdgeKey(edges[seed].first, edges[seed].second)] = 0;
  ring_.push_back(edges[seed]);
  queue.push_back(seed);
  while (!queue.empty()) {
    const int e = queue.front();
    queue.pop_front();
    const auto oriented = ring_[ring_index.at(EdgeKey(edges[e].first, edges[e].second))];
    for (int f : edge_faces[e]) {
      const Polygon& q = input.faces[f];
      if (q.size() != 4) continue;
      int i = 0;
      while (EdgeKey(q[i], q[(i + 1) % 4]) != EdgeKey(oriented.first, oriented.second)) ++i;
      const int c = q[(i + 2) % 4], d = q[(i + 3) % 4];  // edge i+2: c -> d; d adjacent to q[i]
      const int o = edge_index.at(EdgeKey(c, d));
      if (ring_index.count(EdgeKey(c, d)) || !parallel(o)) continue;
      ring_index[EdgeKey(c, d)] = static_cast<int>(ring_.size());
      ring_.push_back(oriented.first == q[i] ? std::make_pair(d, c) : std::make_pair(c, d));
      queue.push_back(o);
    }
  }

  // Cut vertex k (1..cuts) along the directed edge u -> v.
  auto cut = [&](int u, int w, int k) {
    const auto it = ring_index.find(EdgeKey(u, w));
    const int base = num_input_vertices_ + it->second * cuts_ - 1;
    return ring_[it->second].first == u ? base + k : base + cuts_ + 1 - k;
  };
  auto in_ring = [&](int u, int w) { return ring_index.count(EdgeKey(u, w)) > 0; };

  output_faces_.clear();
  for (const Polygon& face : input.faces) {
    const int n = static_cast<int>(face.size());
    int count = 0;
    for (int i = 0; i < n; ++i) count += in_ring(face[i], face[(i + 1) % n]);
    if (count == 0) {
      output_faces_.push_back(face);
      continue;
    }
    if (n == 4 && count == 2) {
      int i = 0;
      while (!in_ring(face[i], face[(i + 1) % 4])) ++i;
      if (in_ring(face[(i + 2) % 4], face[(i + 3) % 4])) {
        const int p0 = face[i], p1 = face[(i + 1) % 4], p2 = face[(i + 2) % 4], p3 = face[(i + 3) % 4];
        auto side_a = [&](int k) { return k == 0 ? p0 : k == cuts_ + 1 ? p1 : cut(p0, p1, k); };
        auto side_b = [&](int k) { return k == 0 ? p3 : k == cuts_ + 1 ? p2 : cut(p3, p2, k); };
        for (int k = 0; k <= cuts_; ++k) {
          output_faces_.push_back({side_a(k), side_a(k + 1), side_b(k + 1), side_b(k)});
        }
        continue;
      }
    }
    Polygon loop;
    for (int i = 0; i < n; ++i) {
      const int a = face[i], b = face[(i + 1) % n];
      loop.push_back(a);
      if (in_ring(a, b)) {
        for (int k = 1; k <= cuts_; ++k) loop.push_back(cut(a, b, k));
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
