#include "solver/affine_tail.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opgraph {
namespace {

// The ops' output for cage positions `in` (double pass, the sequence's parameters and gates).
void EvaluateTail(const Sequence& sequence, int first_op, const Positions<double>& in,
                  std::vector<Positions<double>>* scratch) {
  const Positions<double>* current = &in;
  for (size_t k = first_op; k < sequence.ops.size(); ++k) {
    Positions<double>& out = (*scratch)[k - first_op];
    sequence.ops[k]->Evaluate(sequence.ops[k]->params().data(), sequence.gates[k], *current, &out);
    current = &out;
  }
}

}  // namespace

Positions<double> AffineTail::Apply(const Positions<double>& cage) const {
  Positions<double> out = offset;
  for (size_t o = 0; o < out.size(); ++o) {
    for (const Term& term : terms[o]) out[o] += term.matrix * cage[term.vertex];
  }
  return out;
}

AffineTail ProbeAffineTail(const Sequence& sequence, int first_op, const Mesh& cage, const Mesh& output) {
  const int num_ops = static_cast<int>(sequence.ops.size()) - first_op;
  if (num_ops < 0) throw std::invalid_argument("affine tail: first op beyond the sequence");
  AffineTail tail;
  tail.num_cage_vertices = cage.NumVertices();
  tail.faces = num_ops == 0 ? cage.faces : sequence.ops.back()->output_faces();
  std::vector<Positions<double>> scratch(std::max(num_ops, 1));
  Positions<double> probe(cage.NumVertices(), Vec3d::Zero());
  auto evaluate = [&]() -> const Positions<double>& {
    if (num_ops == 0) return probe;
    EvaluateTail(sequence, first_op, probe, &scratch);
    return scratch[num_ops - 1];
  };
  tail.offset = evaluate();
  const size_t num_outputs = tail.offset.size();
  tail.terms.assign(num_outputs, {});
  double extent = 0;
  for (const Vec3d& p : cage.vertices) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double unit = std::max(extent, 1.0);  // probes of the cage's size keep the rounding relative
  for (int v = 0; v < cage.NumVertices(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      probe[v][axis] = unit;
      const Positions<double>& out = evaluate();
      for (size_t o = 0; o < num_outputs; ++o) {
        const Vec3d column = (out[o] - tail.offset[o]) / unit;
        if (column.cwiseAbs().maxCoeff() <= 1e-13) continue;
        if (tail.terms[o].empty() || tail.terms[o].back().vertex != v) tail.terms[o].push_back({v, Eigen::Matrix3d::Zero()});
        tail.terms[o].back().matrix.col(axis) = column;
      }
      probe[v][axis] = 0;
    }
  }
  // The map must reproduce the sequence's own output at the cage.
  const Positions<double> mapped = tail.Apply(cage.vertices);
  if (mapped.size() != output.vertices.size()) throw std::runtime_error("affine tail: the output size differs");
  double output_extent = 1e-300;
  for (const Vec3d& p : output.vertices) output_extent = std::max(output_extent, p.cwiseAbs().maxCoeff());
  for (size_t o = 0; o < mapped.size(); ++o) {
    if (!((mapped[o] - output.vertices[o]).norm() <= 1e-9 * output_extent)) {
      throw std::runtime_error("affine tail: the ops after the cage are not affine in its positions");
    }
  }
  return tail;
}

}  // namespace opgraph
