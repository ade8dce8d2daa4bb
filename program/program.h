// A sequence with its discrete choices fixed, as a differentiable function of its continuous
// parameters: the output positions and their Jacobian, for Ceres.
//
// Parameter blocks: one per op with fitted parameters (the op's own params array, so Ceres
// writes the op directly) and one per op with a free gate (a logit w, gate = sigmoid(w)).
// A parameter is fitted when it is written to sequence.json (a parameter the JSON does not
// carry, like Subdivision's level_blend, is a fixed internal relaxation and stays constant);
// ops without fitted parameters keep their gate fixed (their gate has no meaning to fit).
//
// Ops evaluate with JetT = ceres::Jet<double, 4> only, so the Jacobian is built by forward mode
// in chunks of 4 directions, each chunk starting at the first op it touches (the positions
// before it are cached doubles). The program is evaluated once per Ceres evaluation point
// (EvaluationCallback) and shared by every residual block through positions() / Jacobian rows.
//
// Branch choices (softmax branch weights for a discrete choice): op k's discrete field takes
// each of K options in one variant of the op, all prepared on op k's input and evaluated with
// op k's own parameters and gate (so the continuous parameters are shared; the variants must
// have op k's parameter layout). A block of K logits alpha gives weights w = softmax(alpha)
// and op k's output is sum_i w_i out_i, so every later op is unchanged and the Jacobian gains
// alpha's K columns (dw_i/dalpha_j = w_i (delta_ij - w_j)) when every variant gives op k's
// output topology. Options of different topology can only be the last op (a "mixed" branch):
// the output is then the variants' outputs side by side (face_options() says which option a
// face belongs to), independent of alpha, and the fitter mixes their Chamfer terms with
// weights w (residuals scaled by sqrt(w_k), residuals/correspondence_cost.h).
#pragma once

#include <ceres/evaluation_callback.h>

#include <memory>
#include <string>
#include <vector>

#include "ops/sequence.h"

namespace opgraph {

struct ProgramBlock {
  double* data;
  int size;
  int op;          // index into the sequence's ops
  bool is_gate;    // a gate logit (size 1) rather than the op's parameters
  int column;      // first Jacobian column of the block
  std::vector<int> constant;  // indices within the block held constant
  bool is_branch = false;      // a branch choice's K logits (no bounds, not a gate)
  bool is_boolean_weight = false;  // an Extrude's Boolean weight logit (solver/boolean_weight.h)
  // Whether the block is the op's parameters (bounded by its specs).
  bool holds_op_params() const { return !is_gate && !is_branch && !is_boolean_weight; }
};

constexpr int kMaxBranchOptions = 16;

// A discrete choice fitted by softmax branch weights: field `field` of op `op`'s JSON params
// takes each of `options` (K >= 2), e.g. Mirror's "axes": [["X"], ["Y"], ["Z"]].
struct BranchChoice {
  int op = -1;
  std::string field;
  std::vector<Json> options;
};

class Program : public ceres::EvaluationCallback {
 public:
  // Runs every op's topology pass once at the sequence's current parameters. `free_gates`: the
  // gates of ops with fitted parameters become parameters (started at min(max(g, 0.02), 0.98)
  // so the sigmoid is not saturated). `branches`: at most one per op, started at uniform
  // weights. `boolean_weight_ops`: Extrude ops (only the last op) given a Boolean weight logit
  // (solver/boolean_weight.h), started at 0 (beta = 0.5); the output does not depend on it.
  // Throws SequenceError like EvaluateSequence, std::invalid_argument (one line naming the op
  // and field) on a branch choice or Boolean weight that cannot be built.
  Program(Sequence* sequence, bool free_gates, const std::vector<BranchChoice>& branches = {},
          const std::vector<int>& boolean_weight_ops = {});

  const std::vector<ProgramBlock>& blocks() const { return blocks_; }
  int num_columns() const { return num_columns_; }
  int num_free_columns() const { return static_cast<int>(free_columns_.size()); }
  std::vector<double*> BlockPointers() const;
  std::vector<int> BlockSizes() const;

  // The gate of op `op` (sigmoid of its logit when free).
  double Gate(int op) const;
  bool GateIsFree(int op) const { return gate_block_[op] >= 0; }
  // Writes the current gates into the sequence.
  void StoreGates() const;
  // Gate logits, one per op (meaningful for free gates).
  const std::vector<double>& logits() const { return logits_; }
  void set_logits(const std::vector<double>& logits) { logits_ = logits; values_ready_ = jacobian_ready_ = false; }

  // Branch choices: their number, the op and current weights softmax(alpha) of branch b.
  int num_branches() const { return static_cast<int>(branches_.size()); }
  int BranchOp(int branch) const { return branches_[branch].choice.op; }
  std::vector<double> BranchWeights(int branch) const;
  // Writes each branch's most weighted option into its op of the sequence (a new op parsed
  // from the op's JSON with that option, keeping its parameters), so the sequence as written
  // chooses it. The program is stale afterwards (its blocks alias the replaced ops): rebuild it.
  void CommitBranches() const;

  // Boolean weights: the block index of op `op`'s logit (-1: none), beta = sigmoid(logit), and
  // all the logits (per op) to carry them over to a rebuilt program.
  int BooleanWeightBlock(int op) const { return boolean_block_[op]; }
  double BooleanWeight(int op) const;
  const std::vector<double>& boolean_logits() const { return boolean_logits_; }
  void set_boolean_logits(const std::vector<double>& logits) { boolean_logits_ = logits; }

  const Sequence& sequence() const { return *sequence_; }
  // #V positions of op `op`'s input at the last evaluation.
  const Positions<double>& InputPositions(int op) const { return steps_[op]; }

  // Evaluates at the current parameter values. Returns false when a position is not finite.
  bool EvaluateValues();
  // Needs EvaluateValues() at the same point first.
  void EvaluateJacobian();
  bool valid() const { return valid_; }

  // Output topology and #V positions.
  const std::vector<Polygon>& faces() const {
    if (!mixed_faces_.empty()) return mixed_faces_;
    return sequence_->ops.empty() ? start_.faces : sequence_->ops.back()->output_faces();
  }
  // A mixed branch (above): its block index (-1: none) and, per output face, its option.
  int MixedBranchBlock() const { return mixed_block_; }
  const std::vector<int>& face_options() const { return face_options_; }
  const Positions<double>& positions() const { return steps_.back(); }
  Mesh OutputMesh() const { return {positions(), faces()}; }
  // The 3 rows (x, y, z) of the #3V by num_columns() row-major Jacobian for `vertex`.
  const double* JacobianRows(int vertex) const { return jacobian_.data() + 3 * static_cast<size_t>(vertex) * num_columns_; }

  void PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) override;

  // Number of program evaluations (values, Jacobians) so far.
  int num_value_evaluations() const { return num_value_evaluations_; }
  int num_jacobian_evaluations() const { return num_jacobian_evaluations_; }

 private:
  Sequence* sequence_;
  Mesh start_;
  std::vector<ProgramBlock> blocks_;
  std::vector<int> param_block_;  // per op: block index of its params or -1
  std::vector<int> gate_block_;   // per op: block index of its gate logit or -1
  std::vector<double> logits_;    // per op
  int num_columns_ = 0;
  struct FreeColumn {
    int op;
    int param;  // -1: the gate (or a branch logit, see option)
    int column;
    int option = -1;  // >= 0: the logit of this option of the op's branch choice
  };
  struct Branch {
    BranchChoice choice;
    std::vector<std::unique_ptr<Op>> variants;  // one per option, prepared on the op's input
    std::vector<double> logits;                 // alpha (the block's data)
    // Scratch (sized once): weights and each variant's output.
    std::vector<double> weights;
    std::vector<JetT> jet_weights;
    std::vector<Positions<double>> outputs;
    std::vector<Positions<JetT>> jet_outputs;
    bool mixed = false;  // options of different topology, side by side in the output
  };
  // The branch choices' variants, prepared on their ops' inputs (`meshes`: each op's output),
  // at uniform weights. Throws std::invalid_argument as the constructor says.
  void AddBranches(const std::vector<BranchChoice>& branches, const std::vector<Mesh>& meshes);
  // Op k's output: its own geometry pass, or the blend of its branch's variants.
  void EvaluateOp(int k, const double* params, const double& gate, const Positions<double>& in,
                  Positions<double>* out);
  void EvaluateOp(int k, const JetT* params, const JetT& gate, const Positions<JetT>& in, Positions<JetT>* out);
  std::vector<Branch> branches_;
  std::vector<int> branch_of_;  // per op: index into branches_ or -1
  std::vector<Polygon> mixed_faces_;  // a mixed branch's output faces, else empty
  std::vector<int> face_options_;
  int mixed_block_ = -1;
  std::vector<int> boolean_block_;       // per op: block index of its Boolean weight or -1
  std::vector<double> boolean_logits_;   // per op
  std::vector<FreeColumn> free_columns_;  // ordered by op

  std::vector<Positions<double>> steps_;  // #ops + 1: the start, then each op's output
  std::vector<double> jacobian_;
  // Scratch for the forward-mode passes (sized once).
  Positions<JetT> jet_in_, jet_out_;
  std::vector<std::vector<JetT>> jet_params_;
  bool valid_ = false, values_ready_ = false, jacobian_ready_ = false;
  int num_value_evaluations_ = 0, num_jacobian_evaluations_ = 0;
};

}  // namespace opgraph
