// The Python module `opgraph` over the C++ API (api/opgraph.h): numpy in and out, sequences as
// dicts (or sequence.json text). README.md, "Python"; test: python/tests/test_opgraph.py.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>

#include "api/opgraph.h"

namespace py = pybind11;

namespace opgraph {
namespace api {
namespace {

// A sequence given as a dict (a parsed sequence.json) or as its text.
std::string SequenceText(const py::object& sequence) {
  if (py::isinstance<py::str>(sequence)) return sequence.cast<std::string>();
  if (py::isinstance<py::dict>(sequence)) return py::module_::import("json").attr("dumps")(sequence).cast<std::string>();
  throw py::type_error("sequence: expected a dict or a JSON string");
}

py::dict SequenceDict(const std::string& sequence_json) {
  return py::module_::import("json").attr("loads")(sequence_json);
}

// {"vertices": #V by 3 float64, "faces": a list of #F int64 index arrays (quads mostly)}.
py::dict MeshDict(const Mesh& mesh) {
  py::list faces;
  for (const std::vector<int>& face : mesh.faces) {
    py::array_t<int64_t> loop(static_cast<py::ssize_t>(face.size()));
    auto indices = loop.mutable_unchecked<1>();
    for (size_t i = 0; i < face.size(); ++i) indices(static_cast<py::ssize_t>(i)) = face[i];
    faces.append(loop);
  }
  py::dict result;
  result["vertices"] = py::cast(mesh.vertices);
  result["faces"] = faces;
  return result;
}

// A fitted sequence as Python gets it: its mesh's dict with the sequence and its op count.
py::dict SequenceResult(const std::string& sequence_json, const Mesh& mesh, int num_ops) {
  py::dict result = MeshDict(mesh);
  result["sequence"] = SequenceDict(sequence_json);
  result["num_ops"] = num_ops;
  return result;
}

// Runs `call` without the GIL, so other Python threads run meanwhile.
template <typename Call>
auto WithoutGil(const Call& call) {
  py::gil_scoped_release release;
  return call();
}

Eigen::MatrixX3d PointArray(const py::object& array, const char* what) {
  try {
    return array.cast<Eigen::MatrixX3d>();
  } catch (const py::cast_error&) {
    throw py::value_error(std::string(what) + ": expected a #P by 3 array of numbers");
  }
}

// A path (str or os.PathLike) to read, or a #P by 3 array of points with optional normals.
Target MakeTarget(const py::object& points_or_path, const py::object& normals, const TargetOptions& options) {
  if (py::isinstance<py::str>(points_or_path) || py::hasattr(points_or_path, "__fspath__")) {
    const std::string path = py::module_::import("os").attr("fspath")(points_or_path).cast<std::string>();
    return WithoutGil([&] { return Target::FromFile(path, options); });
  }
  const Eigen::MatrixX3d points = PointArray(points_or_path, "points");
  const Eigen::MatrixX3d point_normals = normals.is_none() ? Eigen::MatrixX3d() : PointArray(normals, "normals");
  return WithoutGil([&] { return Target::FromPoints(points, point_normals, options); });
}

// Calls a Python callable (or none) from a search running without the GIL: a dict of the
// progress in, False out cancels. Ctrl-C cancels too; the error surfaces when the call returns.
ProgressCallback PythonProgress(py::handle on_progress) {
  return [on_progress](const Progress& progress) {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (on_progress.is_none()) return true;
    py::dict state;
    state["stage"] = progress.stage;
    state["fraction"] = progress.fraction;
    state["seconds"] = progress.seconds;
    state["ops"] = progress.ops;
    state["loss"] = progress.loss;
    state["decision"] = progress.decision;
    const py::object go_on = on_progress(state);
    return go_on.is_none() || go_on.cast<bool>();
  };
}

py::dict Recover(const py::object& points_or_path, const py::object& normals, int64_t work_budget,
                 double time_budget_seconds, int max_ops, double min_relative_gain, int beam_width, uint64_t seed, int num_threads,
                 bool freeform, const py::object& on_progress, int num_samples, int max_cloud_points,
                 int normal_neighbours) {
  TargetOptions target_options;
  target_options.num_samples = num_samples;
  target_options.max_cloud_points = max_cloud_points;
  target_options.normal_neighbours = normal_neighbours;
  target_options.seed = seed;
  RecoverOptions options;
  options.work_budget = work_budget;
  options.time_budget_seconds = time_budget_seconds;
  options.max_ops = max_ops;
  options.min_relative_gain = min_relative_gain;
  options.beam_width = beam_width;
  options.seed = seed;
  options.num_threads = num_threads;
  options.freeform = freeform;
  options.on_progress = PythonProgress(on_progress);
  const Target target = MakeTarget(points_or_path, normals, target_options);
  const RecoverResult recovered = WithoutGil([&] { return RecoverSequence(target, options); });
  py::dict result = SequenceResult(recovered.sequence_json, recovered.mesh, recovered.num_ops);
  result["loss"] = recovered.loss;
  result["work"] = recovered.work;
  result["num_fits"] = recovered.num_fits;
  result["seconds"] = recovered.seconds;
  result["ended_by"] = recovered.ended_by;
  result["decisions"] = recovered.decisions;
  return result;
}

py::dict Fit(const py::object& sequence, const py::object& points_or_path, const py::object& normals,
             bool fit_gates, int max_outer_iterations, int num_samples, uint64_t seed) {
  TargetOptions target_options;
  target_options.seed = seed;
  FitOptions options;
  options.fit_gates = fit_gates;
  options.max_outer_iterations = max_outer_iterations;
  options.num_samples = num_samples;
  options.seed = seed;
  const std::string sequence_json = SequenceText(sequence);
  const Target target = MakeTarget(points_or_path, normals, target_options);
  const FitResult fitted = WithoutGil([&] { return FitSequence(sequence_json, target, options); });
  py::dict result = SequenceResult(fitted.sequence_json, fitted.mesh, fitted.num_ops);
  result["initial_loss"] = fitted.initial_loss;
  result["final_loss"] = fitted.final_loss;
  result["seconds"] = fitted.seconds;
  return result;
}

py::dict Apply(const py::object& sequence) {
  const std::string sequence_json = SequenceText(sequence);
  return MeshDict(WithoutGil([&] { return ApplySequence(sequence_json); }));
}

void Write(const py::object& sequence, const py::object& out_dir, bool write_steps, const std::string& name,
           const std::string& comment) {
  const std::string sequence_json = SequenceText(sequence);
  const std::string dir = py::module_::import("os").attr("fspath")(out_dir).cast<std::string>();
  const WriteOptions options{write_steps, name, comment};
  WithoutGil([&] { WriteOutputs(sequence_json, dir, options); });
}

}  // namespace
}  // namespace api
}  // namespace opgraph

PYBIND11_MODULE(opgraph, module) {
  using namespace opgraph::api;
  module.doc() =
      "opgraph: recover Blender design sequences (GlobalAffineScale, LoopCut, Extrude, Bevel, ...) from meshes and "
      "point clouds. Sequences are dicts in the sequence.json format; meshes are dicts of 'vertices' (#V by 3 "
      "float64) and 'faces' (a list of int64 index arrays). Errors: ValueError for bad input, RuntimeError for "
      "files that cannot be read or written and sequences that do not evaluate.";
  module.attr("__version__") = Version();
  const TargetOptions target_defaults;
  const RecoverOptions recover_defaults;
  const FitOptions fit_defaults;
  const WriteOptions write_defaults;

  module.def("recover", &Recover,
             "Recovers a design sequence for a shape: a file path (mesh or point cloud) or #P by 3 points with "
             "optional #P by 3 normals. on_progress(dict of stage, fraction, seconds, ops, loss, decision) may "
             "return False to cancel (Ctrl-C cancels too). Returns a dict: sequence, vertices, faces, num_ops, "
             "loss, work, num_fits, seconds, ended_by, decisions.",
             py::arg("points_or_path"), py::arg("normals") = py::none(), py::kw_only(),
             py::arg("work_budget") = recover_defaults.work_budget,
             py::arg("time_budget_seconds") = recover_defaults.time_budget_seconds,
             py::arg("max_ops") = recover_defaults.max_ops,
             py::arg("min_relative_gain") = recover_defaults.min_relative_gain,
             py::arg("beam_width") = recover_defaults.beam_width, py::arg("seed") = recover_defaults.seed,
             py::arg("num_threads") = recover_defaults.num_threads, py::arg("freeform") = recover_defaults.freeform,
             py::arg("on_progress") = py::none(), py::arg("num_samples") = target_defaults.num_samples,
             py::arg("max_cloud_points") = target_defaults.max_cloud_points,
             py::arg("normal_neighbours") = target_defaults.normal_neighbours);
  module.def("fit", &Fit,
             "Fits a sequence's continuous parameters (ops and discrete choices kept) to a shape given as in "
             "recover. Returns a dict: sequence, vertices, faces, num_ops, initial_loss, final_loss, seconds.",
             py::arg("sequence"), py::arg("points_or_path"), py::arg("normals") = py::none(), py::kw_only(),
             py::arg("fit_gates") = fit_defaults.fit_gates,
             py::arg("max_outer_iterations") = fit_defaults.max_outer_iterations,
             py::arg("num_samples") = fit_defaults.num_samples, py::arg("seed") = fit_defaults.seed);
  module.def("apply", &Apply, "The mesh a sequence (dict or JSON string) builds: a dict of vertices and faces.",
             py::arg("sequence"));
  module.def("write_outputs", &Write,
             "Writes out_dir/result.obj, result.glb, rebuild_blender.py, sequence.json and (write_steps) "
             "steps/NN_<op>.obj; nothing when the sequence does not evaluate.",
             py::arg("sequence"), py::arg("out_dir"), py::kw_only(), py::arg("write_steps") = write_defaults.write_steps,
             py::arg("name") = write_defaults.name, py::arg("comment") = write_defaults.comment);
}
