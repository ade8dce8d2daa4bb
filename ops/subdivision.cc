#include "ops/subdivision.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <map>
#include <memory>
#include <utility>

#include "ops/face_list_cache.h"

namespace opgraph {
namespace {

using OpenSubdiv::Far::PrimvarRefinerReal;
using OpenSubdiv::Far::TopologyDescriptor;
using OpenSubdiv::Far::TopologyRefiner;
using OpenSubdiv::Far::TopologyRefinerFactory;
namespace Sdc = OpenSubdiv::Sdc;

// A primvar that is a sparse combination of the input vertices, so that running OpenSubdiv's
// own interpolation on it yields the exact refinement weights. Contributions are appended and
// merged when the weights are read (Compact), not kept in a map, which allocates a node per
// term; merged in the order they were added and read in index order, they sum exactly as a map
// would. OpenSubdiv reads some weights of a level while it builds that level (edge points from
// face points), hence the lazy merge.
struct SparseWeights {
  void Clear(void* = nullptr) { terms.clear(), compact = true; }
  void AddWithWeight(const SparseWeights& src, double weight) {
    src.Compact();
    for (const auto& term : src.terms) terms.emplace_back(term.first, weight * term.second);
    compact = false;
  }
  void Compact() const {
    if (compact) return;
    std::stable_sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    size_t kept = 0;
    for (size_t i = 0; i < terms.size(); ++i) {
      if (kept > 0 && terms[kept - 1].first == terms[i].first) {
        terms[kept - 1].second += terms[i].second;
      } else {
        terms[kept++] = terms[i];
      }
    }
    terms.resize(kept);
    compact = true;
  }
  mutable std::vector<std::pair<int, double>> terms;  // once compact: by index, each index once
  mutable bool compact = true;
};

std::unique_ptr<TopologyRefiner> RefineUniformly(const Mesh& input, Sdc::SchemeType scheme, int levels) {
  std::vector<int> counts, indices;
  for (const Polygon& face : input.faces) {
    counts.push_back(static_cast<int>(face.size()));
    indices.insert(indices.end(), face.begin(), face.end());
  }
  TopologyDescriptor descriptor;
  descriptor.numVertices = input.NumVertices();
  descriptor.numFaces = input.NumFaces();
  descriptor.numVertsPerFace = counts.data();
  descriptor.vertIndicesPerFace = indices.data();

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  options.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
  using Factory = TopologyRefinerFactory<TopologyDescriptor>;
  std::unique_ptr<TopologyRefiner> refiner(
      Factory::Create(descriptor, Factory::Options(scheme, options)));
  if (!refiner) throw FieldError("levels", "OpenSubdiv cannot build the input topology");
  TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

// Weights of the last level's vertices (pushed to the limit when `limit`) on the input vertices.
std::vector<SparseWeights> RefinementWeights(const TopologyRefiner& refiner, int num_inputs, bool limit) {
  std::vector<SparseWeights> current(num_inputs);
  for (int v = 0; v < num_inputs; ++v) current[v].terms = {{v, 1.0}};
  const PrimvarRefinerReal<double> primvar(refiner);
  for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
    std::vector<SparseWeights> next(refiner.GetLevel(level).GetNumVertices());
    primvar.Interpolate(level, current, next);
    for (SparseWeights& weights : next) weights.Compact();
    current = std::move(next);
  }
  if (!limit) return current;
  std::vector<SparseWeights> limited(current.size());
  primvar.Limit(current, limited);
  for (SparseWeights& weights : limited) weights.Compact();
  return limited;
}

}  // namespace

SubdivisionOp::SubdivisionOp(const Json& params) {
  ParamReader reader(params);
  levels_ = reader.Integer("levels", 1, 6);
  reader.Finish();
  AddParam("level_blend", 0, 1, 0, 1);
}

bool SubdivisionOp::PredictOutputFaces(int64_t* faces, int64_t* corners) const {
  // The first level splits an n-gon into n quads, each later level a quad into 4.
  *faces = *corners << (2 * (levels_ - 1));
  *corners = 4 * *faces;
  return true;
}

void SubdivisionOp::Prepare(const Mesh& input) {
  if (input.faces.empty()) throw FieldError("levels", "the input mesh has no faces");
  // EvaluateSequence checks its own limit first; this guards callers that prepare ops directly
  // (the search's layouts).
  int64_t faces = static_cast<int64_t>(input.faces.size()), corners = 0;
  for (const Polygon& face : input.faces) corners += static_cast<int64_t>(face.size());
  PredictOutputFaces(&faces, &corners);
  CheckOutputFaces("levels", faces);
  // Thread-safe and shared: the refinement depends on the faces and the level only.
  static FaceListCache<Refinement> cache(8);
  refinement_ = cache.Get(input, levels_, [&] { return Refine(input, levels_); });
  output_faces_ = refinement_->faces;
  num_output_vertices_ = refinement_->num_vertices;
}

std::shared_ptr<const SubdivisionOp::Refinement> SubdivisionOp::Refine(const Mesh& input, int levels) {
  const std::unique_ptr<TopologyRefiner> catmark = RefineUniformly(input, Sdc::SCHEME_CATMARK, levels);
  const std::unique_ptr<TopologyRefiner> bilinear = RefineUniformly(input, Sdc::SCHEME_BILINEAR, levels);
  const auto& last = catmark->GetLevel(levels);
  const auto& last_bilinear = bilinear->GetLevel(levels);
  auto refinement = std::make_shared<Refinement>();
  // Both schemes split every face into quads in the same order; check it rather than assume.
  bool same = last.GetNumVertices() == last_bilinear.GetNumVertices() &&
              last.GetNumFaces() == last_bilinear.GetNumFaces();
  refinement->faces.assign(last.GetNumFaces(), Polygon());
  for (int f = 0; same && f < last.GetNumFaces(); ++f) {
    const auto verts = last.GetFaceVertices(f);
    const auto verts_bilinear = last_bilinear.GetFaceVertices(f);
    same = verts.size() == verts_bilinear.size();
    for (int k = 0; same && k < verts.size(); ++k) {
      same = verts[k] == verts_bilinear[k];
      refinement->faces[f].push_back(verts[k]);
    }
  }
  if (!same) throw FieldError("levels", "internal: bilinear and Catmull-Clark refinements differ");
  refinement->num_vertices = last.GetNumVertices();

  const std::vector<SparseWeights> limit = RefinementWeights(*catmark, input.NumVertices(), true);
  const std::vector<SparseWeights> linear = RefinementWeights(*bilinear, input.NumVertices(), false);
  refinement->rows.assign(refinement->num_vertices, {});
  for (int i = 0; i < refinement->num_vertices; ++i) {
    std::map<int, std::pair<double, double>> merged;
    for (const auto& term : linear[i].terms) merged[term.first].first += term.second;
    for (const auto& term : limit[i].terms) merged[term.first].second += term.second;
    for (const auto& term : merged) refinement->rows[i].push_back({term.first, term.second.first, term.second.second});
  }
  return refinement;
}

template <typename T>
void SubdivisionOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  const T t = gate * p[0];
  if (!refinement_) return out->clear();  // not prepared: no output vertices
  const std::vector<std::vector<Term>>& rows = refinement_->rows;
  out->assign(rows.size(), Vec3<T>::Zero());
  for (size_t i = 0; i < rows.size(); ++i) {
    Vec3<T> linear = Vec3<T>::Zero(), delta = Vec3<T>::Zero();
    for (const Term& term : rows[i]) {
      linear += term.bilinear * in[term.index];
      delta += (term.limit - term.bilinear) * in[term.index];
    }
    (*out)[i] = linear + t * delta;
  }
}

template void SubdivisionOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                           Positions<double>*) const;
template void SubdivisionOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                         Positions<JetT>*) const;

Json SubdivisionOp::ParamsToJson() const { return {{"levels", levels_}}; }

std::string SubdivisionOp::BlenderCode() const {
  const std::string n = std::to_string(levels_);
  return "m = obj.modifiers.new(" + PyWord("Subdivision") + ", " + PyWord("SUBSURF") + ")\n" +
         "m.subdivision_type = " + PyWord("CATMULL_CLARK") + "\n" +
         "m.levels = " + n + "\n" +
         "m.render_levels = " + n + "\n" +
         "m.quality = 3\n" +
         "m.use_limit_surface = " + PyBool(true) + "\n" +
         "m.boundary_smooth = " + PyWord("ALL") + "\n" +
         "m.use_creases = " + PyBool(true) + "\n";
}

}  // namespace opgraph
