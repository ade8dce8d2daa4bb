#include "program/program.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "program/softmax.h"

namespace opgraph {

namespace {

double Sigmoid(double w) { return 1.0 / (1.0 + std::exp(-w)); }
double Logit(double g) { return std::log(g / (1.0 - g)); }

// Whether sequence.json carries parameter `index` of `op` (changing it changes the JSON).
bool IsWrittenToJson(Op* op, int index) {
  double& value = op->mutable_params()[index];
  const ParamSpec& spec = op->specs()[index];
  const double saved = value;
  const Json before = op->ParamsToJson();
  double probe = saved + 0.125 * (std::abs(saved) + 1);
  if (probe > spec.upper) probe = saved - 0.125 * (std::abs(saved) + 1);
  probe = std::max(spec.lower, std::min(spec.upper, probe));
  value = probe;
  const Json after = op->ParamsToJson();
  value = saved;
  return probe != saved && before != after;
}

}  // namespace

Program::Program(Sequence* sequence, bool free_gates, const std::vector<BranchChoice>& branches,
                 const std::vector<int>& boolean_weight_ops)
    : sequence_(sequence), start_(sequence->StartMesh()) {
  const std::vector<Mesh> meshes = EvaluateSequence(sequence);  // topology passes (discrete choices)
  const int num_ops = static_cast<int>(sequence->ops.size());
  steps_.push_back(start_.vertices);
  for (const Mesh& m : meshes) steps_.push_back(m.vertices);
  AddBranches(branches, meshes);
  boolean_block_.assign(num_ops, -1);
  boolean_logits_.assign(num_ops, 0.0);
  std::vector<bool> boolean_weighted(num_ops, false);
  for (int op : boolean_weight_ops) {
    const std::string label = "Boolean weight on op " + std::to_string(op);
    if (op < 0 || op >= num_ops) throw std::invalid_argument(label + ": not in the sequence");
    if (sequence->ops[op]->Name() != "Extrude") throw std::invalid_argument(label + ": not an Extrude");
    // Its residuals need the extrusion's faces in the output (solver/boolean_weight.h).
    if (op != num_ops - 1) throw std::invalid_argument(label + ": only the last op can have one");
    if (branch_of_[op] >= 0 && branches_[branch_of_[op]].mixed) {
      throw std::invalid_argument(label + ": not with a branch choice of different topologies on it");
    }
    boolean_weighted[op] = true;
  }
  param_block_.assign(num_ops, -1);
  gate_block_.assign(num_ops, -1);
  logits_.assign(num_ops, 0.0);
  jet_params_.resize(num_ops);
  size_t max_vertices = start_.vertices.size();
  for (int k = 0; k < num_ops; ++k) {
    Op* op = sequence->ops[k].get();
    max_vertices = std::max<size_t>(max_vertices, op->num_output_vertices());
    jet_params_[k].resize(op->params().size());
    std::vector<int> constant, fitted;
    for (int i = 0; i < static_cast<int>(op->params().size()); ++i) {
      (IsWrittenToJson(op, i) ? fitted : constant).push_back(i);
    }
    if (!fitted.empty()) {
      param_block_[k] = static_cast<int>(blocks_.size());
      blocks_.push_back({op->mutable_params().data(), static_cast<int>(op->params().size()), k, false, num_columns_, constant});
      for (int i : fitted) free_columns_.push_back({k, i, num_columns_ + i});
      num_columns_ += static_cast<int>(op->params().size());
    }
    // A pinned op keeps its gate (and parameters) as given: no gate block, so it is not blended.
    if (free_gates && !fitted.empty() && !sequence->IsPinned(static_cast<size_t>(k))) {
      logits_[k] = Logit(std::min(0.98, std::max(0.02, sequence->gates[k])));
      gate_block_[k] = static_cast<int>(blocks_.size());
      blocks_.push_back({&logits_[k], 1, k, true, num_columns_, {}});
      free_columns_.push_back({k, -1, num_columns_});
      num_columns_ += 1;
    }
    if (branch_of_[k] >= 0) {
      Branch& branch = branches_[branch_of_[k]];
      const int size = static_cast<int>(branch.logits.size());
      if (branch.mixed) mixed_block_ = static_cast<int>(blocks_.size());
      blocks_.push_back({branch.logits.data(), size, k, false, num_columns_, {}, true});
      // A mixed branch's output does not depend on its logits (zero columns).
      for (int i = 0; i < size && !branch.mixed; ++i) free_columns_.push_back({k, -1, num_columns_ + i, i});
      num_columns_ += size;
    }
    if (boolean_weighted[k]) {  // no free column: the positions do not depend on it
      boolean_block_[k] = static_cast<int>(blocks_.size());
      blocks_.push_back({&boolean_logits_[k], 1, k, false, num_columns_, {}, false, true});
      num_columns_ += 1;
    }
  }
  if (mixed_block_ >= 0) {  // the output until the first evaluation: the variants' sizes
    const Branch& branch = branches_[branch_of_[num_ops - 1]];
    size_t total = 0;
    for (const std::unique_ptr<Op>& variant : branch.variants) total += variant->num_output_vertices();
    steps_.back().assign(total, Vec3d::Zero());
    max_vertices = std::max(max_vertices, total);
  }
  jet_in_.reserve(max_vertices);
  jet_out_.reserve(max_vertices);
  jacobian_.assign(3 * positions().size() * num_columns_, 0.0);
}

std::vector<double*> Program::BlockPointers() const {
  std::vector<double*> pointers;
  pointers.reserve(blocks_.size());
  for (const ProgramBlock& b : blocks_) pointers.push_back(b.data);
  return pointers;
}

std::vector<int> Program::BlockSizes() const {
  std::vector<int> sizes;
  sizes.reserve(blocks_.size());
  for (const ProgramBlock& b : blocks_) sizes.push_back(b.size);
  return sizes;
}

double Program::Gate(int op) const {
  return gate_block_[op] >= 0 ? Sigmoid(logits_[op]) : sequence_->gates[op];
}

double Program::BooleanWeight(int op) const { return Sigmoid(boolean_logits_[op]); }

void Program::StoreGates() const {
  for (size_t k = 0; k < sequence_->ops.size(); ++k) sequence_->gates[k] = Gate(static_cast<int>(k));
}

bool Program::EvaluateValues() {
  ++num_value_evaluations_;
  valid_ = true;
  for (size_t k = 0; k < sequence_->ops.size(); ++k) {
    const Op& op = *sequence_->ops[k];
    const double gate = Gate(static_cast<int>(k));
    EvaluateOp(static_cast<int>(k), op.params().data(), gate, steps_[k], &steps_[k + 1]);
  }
  for (const Vec3d& p : positions()) {
    if (!p.allFinite()) {
      valid_ = false;
      break;
    }
  }
  values_ready_ = true;
  return valid_;
}

void Program::EvaluateJacobian() {
  ++num_jacobian_evaluations_;
  const int num_ops = static_cast<int>(sequence_->ops.size());
  const int num_vertices = static_cast<int>(positions().size());
  for (size_t chunk = 0; chunk < free_columns_.size(); chunk += kJetDim) {
    const size_t chunk_end = std::min(free_columns_.size(), chunk + kJetDim);
    const int first_op = free_columns_[chunk].op;
    const Positions<double>& start = steps_[first_op];
    jet_in_.resize(start.size());
    for (size_t v = 0; v < start.size(); ++v) {
      for (int d = 0; d < 3; ++d) jet_in_[v][d] = JetT(start[v][d]);
    }
    for (int k = first_op; k < num_ops; ++k) {
      const Op& op = *sequence_->ops[k];
      std::vector<JetT>& params = jet_params_[k];
      for (size_t i = 0; i < params.size(); ++i) params[i] = JetT(op.params()[i]);
      JetT gate(Gate(k));
      Branch* branch = branch_of_[k] >= 0 ? &branches_[branch_of_[k]] : nullptr;
      if (branch) {
        Softmax(branch->logits, &branch->weights);
        for (size_t i = 0; i < branch->weights.size(); ++i) branch->jet_weights[i] = JetT(branch->weights[i]);
      }
      for (size_t c = chunk; c < chunk_end; ++c) {
        const FreeColumn& column = free_columns_[c];
        if (column.op != k) continue;
        if (column.option >= 0) {
          const std::vector<double>& w = branch->weights;
          for (size_t i = 0; i < w.size(); ++i) {
            branch->jet_weights[i].v[c - chunk] = w[i] * ((static_cast<int>(i) == column.option) - w[column.option]);
          }
        } else if (column.param >= 0) {
          params[column.param].v[c - chunk] = 1.0;
        } else {
          gate.v[c - chunk] = gate.a * (1.0 - gate.a);  // d sigmoid / d logit
        }
      }
      EvaluateOp(k, params.data(), gate, jet_in_, &jet_out_);
      jet_in_.swap(jet_out_);
    }
    for (int v = 0; v < num_vertices; ++v) {
      for (int d = 0; d < 3; ++d) {
        double* row = jacobian_.data() + (3 * static_cast<size_t>(v) + d) * num_columns_;
        for (size_t c = chunk; c < chunk_end; ++c) row[free_columns_[c].column] = jet_in_[v][d].v[c - chunk];
      }
    }
  }
  jacobian_ready_ = true;
}

void Program::PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) {
  if (new_evaluation_point) values_ready_ = jacobian_ready_ = false;
  if (!values_ready_) EvaluateValues();
  if (evaluate_jacobians && !jacobian_ready_ && valid_) EvaluateJacobian();
}

}  // namespace opgraph
