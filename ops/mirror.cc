#include "ops/mirror.h"

#include <algorithm>

namespace opgraph {

namespace {
constexpr double kMergeThreshold = 0.001;  // Blender's default merge distance
const std::vector<std::string> kAxes = {"X", "Y", "Z"};
}  // namespace

MirrorOp::MirrorOp(const Json& params) {
  ParamReader reader(params);
  const Json& axes = reader.Raw("axes");
  if (!axes.is_array() || axes.empty() || axes.size() > 3) throw FieldError("axes", "must be a list of 1 to 3 of X, Y, Z");
  for (const Json& a : axes) {
    if (!a.is_string() || std::find(kAxes.begin(), kAxes.end(), a.get<std::string>()) == kAxes.end()) {
      throw FieldError("axes", "entries must be X, Y or Z");
    }
    const int k = a.get<std::string>()[0] - 'X';
    if (axes_[k]) throw FieldError("axes", "axis " + kAxes[k] + " listed twice");
    axes_[k] = true;
  }
  reader.Finish();
}

void MirrorOp::Prepare(const Mesh& input) {
  Mesh mesh = input;
  sources_.clear();
  for (int v = 0; v < input.NumVertices(); ++v) sources_.push_back({v, {kKeep, kKeep, kKeep}});
  for (int axis = 0; axis < 3; ++axis) {
    if (!axes_[axis]) continue;
    const int n = mesh.NumVertices();
    std::vector<int> copy_of(n);
    std::vector<bool> welded(n);
    for (int v = 0; v < n; ++v) {
      welded[v] = 2 * std::abs(mesh.vertices[v][axis]) < kMergeThreshold;
      if (welded[v]) {
        copy_of[v] = v;
        mesh.vertices[v][axis] = 0;
        sources_[v].role[axis] = kWelded;
      } else {
        copy_of[v] = mesh.NumVertices();
        Vec3d p = mesh.vertices[v];
        p[axis] = -p[axis];
        mesh.vertices.push_back(p);
        Source s = sources_[v];
        s.role[axis] = kMirrored;
        sources_.push_back(s);
      }
    }
    const size_t num_faces = mesh.faces.size();
    for (size_t f = 0; f < num_faces; ++f) {
      // Blender's loop order for a mirrored face: the first corner kept, the rest reversed.
      Polygon mirrored = mesh.faces[f];
      std::reverse(mirrored.begin() + 1, mirrored.end());
      bool all_welded = true;
      for (int& v : mirrored) {
        all_welded = all_welded && welded[v];
        v = copy_of[v];
      }
      if (!all_welded) mesh.faces.push_back(mirrored);
    }
  }
  output_faces_ = mesh.faces;
  num_output_vertices_ = mesh.NumVertices();
}

template <typename T>
void MirrorOp::Apply(const T*, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  out->resize(sources_.size());
  for (size_t i = 0; i < sources_.size(); ++i) {
    Vec3<T> p = in[sources_[i].vertex];
    for (int axis = 0; axis < 3; ++axis) {
      if (sources_[i].role[axis] == kMirrored) p[axis] *= T(1) - T(2) * gate;
      if (sources_[i].role[axis] == kWelded) p[axis] *= T(1) - gate;
    }
    (*out)[i] = p;
  }
}

template void MirrorOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                      Positions<double>*) const;
template void MirrorOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json MirrorOp::ParamsToJson() const {
  Json axes = Json::array();
  for (int k = 0; k < 3; ++k) {
    if (axes_[k]) axes.push_back(kAxes[k]);
  }
  return {{"axes", axes}};
}

std::string MirrorOp::BlenderCode() const {
  return "m = obj.modifiers.new('Mirror', 'MIRROR')\n"
         "m.use_axis = (" + PyBool(axes_[0]) + ", " + PyBool(axes_[1]) + ", " + PyBool(axes_[2]) + ")\n"
         "m.use_bisect_axis = (False, False, False)\n"
         "m.use_clip = False\n"
         "m.use_mirror_merge = True\n"
         "m.merge_threshold = " + Py(kMergeThreshold) + "\n";
}

}  // namespace opgraph
