// An operation of the design sequence: a topology pass (discrete choices, run once per choice on
// double positions) and a geometry pass templated on the scalar type, so ceres::Jet
// differentiates it. Each op also owns its JSON form and its Blender export.
#pragma once

#include <ceres/jet.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "ops/limits.h"
#include "ops/params.h"

namespace opgraph {

constexpr int kJetDim = 4;
using JetT = ceres::Jet<double, kJetDim>;

// The value part of a double or Jet (for branch decisions that must not depend on derivatives).
inline double Scalar(double x) { return x; }
template <int N>
double Scalar(const ceres::Jet<double, N>& x) { return x.a; }

// One continuous parameter: its name (as in derivative reports), its bounds for optimisation,
// and the value at which the op is the identity (used by the gate).
struct ParamSpec {
  std::string name;
  double lower;
  double upper;
  double identity;
};

// How an op appears in Blender.
enum class BlenderStage {
  kMeshEdit,  // edits the mesh data: the modifiers above it are applied first
  kModifier,  // a modifier on the object's stack
  kTransform, // a global transform: the object's transform where the modifiers after it allow
};

class Op {
 public:
  virtual ~Op() = default;
  virtual std::string Name() const = 0;

  const std::vector<ParamSpec>& specs() const { return specs_; }
  const std::vector<double>& params() const { return params_; }
  std::vector<double>& mutable_params() { return params_; }

  // Topology pass on the op's input. Resolves discrete choices and fixes the output topology.
  // Throws FieldError when a target does not exist on `input`.
  virtual void Prepare(const Mesh& input) = 0;
  const std::vector<Polygon>& output_faces() const { return output_faces_; }
  // The faces and face corners Prepare would output on an input with `faces` faces and
  // `corners` corners, when the op knows them from the counts alone (Subdivision: 4x a level);
  // false otherwise. EvaluateSequence refuses a step above its limit before the step, and before
  // the steps ahead of it in a run of such ops, allocate anything.
  virtual bool PredictOutputFaces(int64_t* /*faces*/, int64_t* /*corners*/) const { return false; }
  // The most faces Prepare may output (EvaluateSequence passes Sequence::max_faces). An op whose
  // output size depends on its input's topology (LoopCut: the ring it finds) checks it before it
  // builds that output.
  void set_max_output_faces(int64_t faces) { max_output_faces_ = faces; }
  int64_t max_output_faces() const { return max_output_faces_; }
  // Output topology at `gate`: output_faces(), except for an op whose gate is a hard switch
  // (Boolean: the identity below 0.5), where Evaluate writes this topology's positions.
  virtual const std::vector<Polygon>& OutputFaces(double /*gate*/) const { return output_faces_; }
  int num_output_vertices() const { return num_output_vertices_; }

  // Geometry pass. `params` has specs().size() entries; `gate` in [0, 1] blends the op toward
  // the identity (0: the input surface unchanged, in the op's output topology; 1: the full op).
  // `in` holds the input positions (the topology given to Prepare); `out` gets
  // num_output_vertices() positions.
  virtual void Evaluate(const double* params, const double& gate, const Positions<double>& in,
                        Positions<double>* out) const = 0;
  virtual void Evaluate(const JetT* params, const JetT& gate, const Positions<JetT>& in,
                        Positions<JetT>* out) const = 0;

  // The "params" object of sequence.json.
  virtual Json ParamsToJson() const = 0;
  // Python statements applying the op to the object `obj` in rebuild_blender.py, using the
  // helpers of ops/blender_export.h.
  virtual std::string BlenderCode() const = 0;
  // How rebuild_blender.py realises the op (ops/blender_script.cc plans the script from this).
  virtual BlenderStage Stage() const { return BlenderStage::kMeshEdit; }
  // For a modifier: moving a global transform from before the op to after it builds the same
  // mesh (`rigid`: the transform is a rotation or translation).
  virtual bool CommutesWithTransform(bool /*rigid*/) const { return false; }
  // True when the input positions `in` (of the topology given to Prepare) sit within float32
  // noise of a switch in a branch the geometry pass takes on them at these parameters and
  // `gate`: real Blender, on float32 coordinates, may take the other side (a replay guard,
  // ops/replay_guards.h).
  virtual bool NearGeometricBranch(double /*gate*/, const Positions<double>& /*in*/) const { return false; }
  // Loop starts (each polygon's first corner), for a replay guard (ops/replay_guards.h): the
  // output faces at `gate` whose loop start may differ from Blender's, and the input faces
  // whose loop start decides this op's output topology.
  virtual std::vector<int> FacesOfUnknownLoopStart(double /*gate*/) const { return {}; }
  virtual std::vector<int> FacesWhoseLoopStartDecides(double /*gate*/) const { return {}; }

 protected:
  void AddParam(const std::string& name, double lower, double upper, double identity,
                double value) {
    specs_.push_back({name, lower, upper, identity});
    params_.push_back(value);
  }
  // Throws a FieldError on `field` when `faces` is above max_output_faces().
  void CheckOutputFaces(const std::string& field, int64_t faces) const {
    if (faces > max_output_faces_) {
      throw FieldError(field, "would make " + std::to_string(faces) + " faces, above the limit of " +
                                  std::to_string(max_output_faces_));
    }
  }
  // For ops whose topology is the input's.
  void KeepTopology(const Mesh& input) {
    output_faces_ = input.faces;
    num_output_vertices_ = input.NumVertices();
  }

  std::vector<ParamSpec> specs_;
  std::vector<double> params_;
  std::vector<Polygon> output_faces_;
  int num_output_vertices_ = 0;
  int64_t max_output_faces_ = kMaxFacesCeiling;
};

// Forwards both Evaluate overloads to Derived::Apply<T>.
template <class Derived>
class OpBase : public Op {
 public:
  void Evaluate(const double* params, const double& gate, const Positions<double>& in,
                Positions<double>* out) const final {
    static_cast<const Derived*>(this)->Apply(params, gate, in, out);
  }
  void Evaluate(const JetT* params, const JetT& gate, const Positions<JetT>& in,
                Positions<JetT>* out) const final {
    static_cast<const Derived*>(this)->Apply(params, gate, in, out);
  }
};

// Creates an op from its canonical name and "params" object. Throws FieldError on bad
// parameters and std::invalid_argument on an unknown name.
std::unique_ptr<Op> CreateOp(const std::string& name, const Json& params);
// Canonical names of all implemented ops.
std::vector<std::string> OpNames();

}  // namespace opgraph
