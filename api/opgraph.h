// opgraph's entry header: one include for a program that recovers, fits, replays or writes
// design sequences (library opgraph::api; installed as include/opgraph/api/opgraph.h, included
// as "api/opgraph.h"). Nothing here exposes JSON, Ceres, PCL or Assimp types: a sequence is its
// sequence.json text (docs/sequence-format.md), a mesh or point cloud is Eigen arrays.
//
//   opgraph::api::Target target = opgraph::api::Target::FromFile("scan.ply");
//   opgraph::api::RecoverOptions options;
//   options.work_budget = 60000;
//   const opgraph::api::RecoverResult result = opgraph::api::RecoverSequence(target, options);
//   opgraph::api::WriteOutputs(result.sequence_json, "out");
//
// Threads: every function may run on several threads at once, on the same or different
// Targets (a Target never changes after it is made, so one may be shared) and, for
// WriteOutputs, into different folders. Two recoveries
// running together give the same sequences as run one after the other (test:
// Api.ConcurrentRecoveriesMatchSequentialOnes). Callbacks run on the calling thread.
//
// Global state: none is left changed. While a file is read, PCL's process-wide verbosity is
// lowered and Assimp's DefaultLogger is borrowed (or made and removed), then restored
// (io/read_input.h). Ceres logs through glog, which opgraph neither initialises nor configures:
// the host's settings apply (fit_sequence sets FLAGS_minloglevel to hide Ceres' warnings about
// rejected steps). Threads a call starts (num_threads) end before it returns.
//
// Errors: std::invalid_argument for invalid options (the Check() message), points or a
// sequence_json that is not a valid sequence document; std::runtime_error for a file that cannot
// be read or written and a sequence that does not evaluate. Messages are one line.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace opgraph {
class Target;

namespace api {

// The library's version (the CMake package's and every tool's --version).
std::string Version();

// A polygon mesh, in the frame and units of the target it was fitted to.
struct Mesh {
  Eigen::MatrixX3d vertices;            // #V by 3
  std::vector<std::vector<int>> faces;  // #F loops of vertex indices, counter-clockwise from outside
};

// The option structs' constructors set the library's defaults (as `fit_sequence --help` lists
// them); Check() returns empty when valid, else the problem.
struct TargetOptions {
  TargetOptions();
  int num_samples;        // surface samples of a mesh target (a point cloud keeps its points)
  int max_cloud_points;   // larger clouds are subsampled (seeded)
  int normal_neighbours;  // nearest points used to estimate a cloud's missing normals
  uint64_t seed;
  std::string Check() const;
};

// The shape a sequence is recovered or fitted for. Cheap to copy (copies share the data).
class Target {
 public:
  // Any mesh or point cloud format io/read_input.h reads (OBJ, PLY, STL, OFF, glTF, FBX, PCD,
  // XYZ, ...), in the file's frame and units.
  static Target FromFile(const std::string& path, const TargetOptions& options = TargetOptions());
  // A point cloud: `points` #P by 3; `normals` #P by 3 (normalised here) or empty to estimate
  // them. From a PCL cloud without NaNs (pcl::removeNaNFromPointCloud), say of pcl::PointNormal:
  //   points = cloud.getMatrixXfMap(3, 12, 0).transpose().cast<double>();
  //   normals = cloud.getMatrixXfMap(3, 12, 4).transpose().cast<double>();
  // (stride sizeof(PointT) / sizeof(float); pcl::PointXYZ: getMatrixXfMap(3, 4, 0)).
  static Target FromPoints(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals = Eigen::MatrixX3d(),
                           const TargetOptions& options = TargetOptions());
  // A polygon mesh in memory.
  static Target FromMesh(const Mesh& mesh, const TargetOptions& options = TargetOptions());

  bool is_point_cloud() const;
  // The input as given: its vertices or points, and its faces (none for a point cloud).
  Mesh shape() const;
  // The samples the fits use (#N by 3 positions and unit normals).
  Eigen::MatrixX3d sample_points() const;
  Eigen::MatrixX3d sample_normals() const;

 private:
  explicit Target(std::shared_ptr<const opgraph::Target> target);
  friend const opgraph::Target& Internal(const Target& target);
  std::shared_ptr<const opgraph::Target> target_;
};

// Where a recovery stands, passed to RecoverOptions::on_progress.
struct Progress {
  std::string stage;     // "search" while proposals are fitted, then "finish: <step>"
  double fraction = 0;   // of the run done, in [0, 1] (of the work budget, then the finishing steps)
  double seconds = 0;    // wall time so far
  int ops = 0;           // in the best sequence so far
  double loss = 0;       // its data loss: mean squared Chamfer distances, both ways, in the
                         // target's unit box
  std::string decision;  // the decision just taken (a RecoverResult::decisions line), or empty
};
// Returns false to cancel: the best sequence so far is finished and returned. An exception it
// throws cancels too, and RecoverSequence rethrows it.
using ProgressCallback = std::function<bool(const Progress&)>;

struct RecoverOptions {
  RecoverOptions();
  // The budget in work units (Jacobian evaluations times their size; docs/zero-shot.md): not
  // wall time, so a seed gives the same result on every machine, load and thread count.
  int64_t work_budget;
  double time_budget_seconds;  // a wall-time cap (0: none); when it ends a run, results vary
  int max_ops;
  double min_relative_gain;    // a proposal must lower the loss by this fraction per op it adds
  int beam_width;              // main forms the search continues from (1: greedy)
  uint64_t seed;
  int num_threads;             // candidate fits run in parallel (the result is the same for any count)
  bool freeform;               // per-vertex detail last, when it pays for itself
  ProgressCallback on_progress;  // optional
  std::string Check() const;
};

struct RecoverResult {
  std::string sequence_json;  // the sequence.json document
  Mesh mesh;                  // the sequence's result
  int num_ops = 0;
  double loss = 0;            // final data loss (as Progress::loss)
  int64_t work = 0;           // work units spent
  int num_fits = 0;
  double seconds = 0;
  std::string ended_by;       // "complete", "work budget", "time budget" or "cancelled"
  std::vector<std::string> decisions;  // one line per accepted or rejected proposal
};

// Recovers a design sequence for `target` from scratch (the zero-shot search,
// docs/zero-shot.md). Deterministic for a seed unless the time cap or a cancel ends it.
RecoverResult RecoverSequence(const Target& target, const RecoverOptions& options = RecoverOptions());

struct FitOptions {
  FitOptions();
  bool fit_gates;            // also fit each op's gate and remove the ops whose gate falls low
  int max_outer_iterations;  // correspondence updates per stage
  int num_samples;           // samples per correspondence update, each way
  uint64_t seed;
  std::string Check() const;
};

struct FitResult {
  std::string sequence_json;  // the fitted sequence
  Mesh mesh;
  int num_ops = 0;
  double initial_loss = 0, final_loss = 0;  // data loss (as Progress::loss)
  double seconds = 0;
};

// Fits every continuous parameter of `sequence_json` (ops and discrete choices kept, its
// parameters the start, pinned ops held) to `target` (docs/fitting.md).
FitResult FitSequence(const std::string& sequence_json, const Target& target, const FitOptions& options = FitOptions());

// The mesh `sequence_json` builds.
Mesh ApplySequence(const std::string& sequence_json);

struct WriteOptions {
  bool write_steps = true;  // also steps/NN_<op>.obj, the mesh after each op
  // Names the sequence (sequence.json's "name") and its Blender object (rebuild_blender.py);
  // empty: the sequence's own name, else the object is "opgraph".
  std::string name;
  std::string comment = "opgraph result";  // result.obj's header line
};

// Writes OUT_DIR/result.obj, result.glb, rebuild_blender.py, sequence.json (and steps/),
// creating OUT_DIR; each file is written whole or not at all, and nothing when the sequence
// does not evaluate.
void WriteOutputs(const std::string& sequence_json, const std::string& out_dir,
                  const WriteOptions& options = WriteOptions());

}  // namespace api
}  // namespace opgraph
