// Branch choices (program/program.h): a discrete field of an op fitted as a softmax over its
// options' variants, blended (one topology) or side by side (the last op's, of different
// topologies), and the argmax written back into the sequence.
#include <algorithm>
#include <stdexcept>

#include "program/program.h"
#include "program/softmax.h"

namespace opgraph {
namespace {

// Blends the variants' outputs: out = sum_i weights[i] outputs[i] (all of one topology).
template <typename T>
void BlendVariants(const std::vector<std::unique_ptr<Op>>& variants, const std::vector<T>& weights, const T* params,
                   const T& gate, const Positions<T>& in, std::vector<Positions<T>>* outputs, Positions<T>* out) {
  for (size_t i = 0; i < variants.size(); ++i) variants[i]->Evaluate(params, gate, in, &(*outputs)[i]);
  out->resize((*outputs)[0].size());
  for (size_t v = 0; v < out->size(); ++v) {
    Vec3<T> p = weights[0] * (*outputs)[0][v];
    for (size_t i = 1; i < variants.size(); ++i) p += weights[i] * (*outputs)[i][v];
    (*out)[v] = p;
  }
}

// The variants' outputs side by side (a mixed branch).
template <typename T>
void ConcatenateVariants(const std::vector<std::unique_ptr<Op>>& variants, const T* params, const T& gate,
                         const Positions<T>& in, std::vector<Positions<T>>* outputs, Positions<T>* out) {
  size_t total = 0;
  for (size_t i = 0; i < variants.size(); ++i) {
    variants[i]->Evaluate(params, gate, in, &(*outputs)[i]);
    total += (*outputs)[i].size();
  }
  out->resize(total);
  auto next = out->begin();
  for (const Positions<T>& output : *outputs) next = std::copy(output.begin(), output.end(), next);
}

// Variant `option` of `op`: the op parsed from its JSON with field := option, prepared on
// `input`. Throws std::invalid_argument naming the op and field.
std::unique_ptr<Op> MakeVariant(const Op& op, int index, const std::string& field, const Json& option,
                                const Mesh& input) {
  const std::string label = "branch choice on op " + std::to_string(index) + " (" + op.Name() + ") field '" + field + "'";
  Json params = op.ParamsToJson();
  if (!params.contains(field)) throw std::invalid_argument(label + ": not a field of the op");
  params[field] = option;
  std::unique_ptr<Op> variant;
  try {
    variant = CreateOp(op.Name(), params);
    variant->set_max_output_faces(op.max_output_faces());
    variant->Prepare(input);
  } catch (const std::exception& e) {
    throw std::invalid_argument(label + ": option " + option.dump() + ": " + e.what());
  }
  if (variant->specs().size() != op.specs().size()) {
    throw std::invalid_argument(label + ": option " + option.dump() + " changes the op's parameters");
  }
  return variant;
}

}  // namespace

void Program::AddBranches(const std::vector<BranchChoice>& branches, const std::vector<Mesh>& meshes) {
  const int num_ops = static_cast<int>(sequence_->ops.size());
  branch_of_.assign(num_ops, -1);
  branches_.reserve(branches.size());  // the logits' addresses are parameter blocks
  for (const BranchChoice& choice : branches) {
    if (choice.op < 0 || choice.op >= num_ops) {
      throw std::invalid_argument("branch choice: op " + std::to_string(choice.op) + " is not in the sequence");
    }
    if (branch_of_[choice.op] >= 0) throw std::invalid_argument("branch choice: op " + std::to_string(choice.op) + " listed twice");
    if (choice.options.size() < 2 || static_cast<int>(choice.options.size()) > kMaxBranchOptions) {
      throw std::invalid_argument("branch choice on op " + std::to_string(choice.op) + ": needs 2 to " +
                                  std::to_string(kMaxBranchOptions) + " options");
    }
    const Op& op = *sequence_->ops[choice.op];
    const Mesh input = choice.op == 0 ? start_ : meshes[choice.op - 1];
    Branch branch;
    branch.choice = choice;
    for (const Json& option : choice.options) {
      branch.variants.push_back(MakeVariant(op, choice.op, choice.field, option, input));
    }
    for (const std::unique_ptr<Op>& variant : branch.variants) {
      branch.mixed = branch.mixed || variant->output_faces() != op.output_faces() ||
                     variant->num_output_vertices() != op.num_output_vertices();
    }
    if (branch.mixed) {
      if (choice.op != num_ops - 1) {
        throw std::invalid_argument("branch choice on op " + std::to_string(choice.op) + " (" + op.Name() + ") field '" +
                                    choice.field + "': its options give different topologies, supported only on the last op");
      }
      for (size_t i = 0, offset = 0; i < branch.variants.size(); ++i) {
        for (Polygon face : branch.variants[i]->output_faces()) {
          for (int& v : face) v += static_cast<int>(offset);
          mixed_faces_.push_back(face);
          face_options_.push_back(static_cast<int>(i));
        }
        offset += branch.variants[i]->num_output_vertices();
      }
    }
    const size_t k = choice.options.size();
    branch.logits.assign(k, 0.0);
    branch.outputs.resize(k);
    branch.jet_outputs.resize(k);
    branch.jet_weights.resize(k);
    Softmax(branch.logits, &branch.weights);
    branch_of_[choice.op] = static_cast<int>(branches_.size());
    branches_.push_back(std::move(branch));
  }
}

std::vector<double> Program::BranchWeights(int branch) const {
  std::vector<double> weights;
  Softmax(branches_[branch].logits, &weights);
  return weights;
}

void Program::CommitBranches() const {
  for (const Branch& branch : branches_) {
    const std::vector<double>& logits = branch.logits;
    const size_t best = std::max_element(logits.begin(), logits.end()) - logits.begin();
    std::unique_ptr<Op>& op = sequence_->ops[branch.choice.op];
    Json params = op->ParamsToJson();
    params[branch.choice.field] = branch.choice.options[best];
    op = CreateOp(op->Name(), params);  // parsed before (MakeVariant), so valid
  }
}

void Program::EvaluateOp(int k, const double* params, const double& gate, const Positions<double>& in,
                         Positions<double>* out) {
  if (branch_of_[k] < 0) return sequence_->ops[k]->Evaluate(params, gate, in, out);
  Branch& branch = branches_[branch_of_[k]];
  if (branch.mixed) return ConcatenateVariants(branch.variants, params, gate, in, &branch.outputs, out);
  Softmax(branch.logits, &branch.weights);
  BlendVariants(branch.variants, branch.weights, params, gate, in, &branch.outputs, out);
}

void Program::EvaluateOp(int k, const JetT* params, const JetT& gate, const Positions<JetT>& in,
                         Positions<JetT>* out) {
  if (branch_of_[k] < 0) return sequence_->ops[k]->Evaluate(params, gate, in, out);
  Branch& branch = branches_[branch_of_[k]];
  if (branch.mixed) return ConcatenateVariants(branch.variants, params, gate, in, &branch.jet_outputs, out);
  BlendVariants(branch.variants, branch.jet_weights, params, gate, in, &branch.jet_outputs, out);
}

}  // namespace opgraph
