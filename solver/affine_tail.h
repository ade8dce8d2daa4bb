// The last ops of a sequence as an affine map of an earlier step's positions. Subdivision
// (its stencils at a fixed level blend) and the global affine ops are affine in their input
// positions, so after them every output vertex is a fixed, sparse combination of the cage's
// vertices: output_o = offset_o + sum_v M_ov x_v. Free-form displacements of the cage enter the
// output linearly through it, with no forward-mode pass per displaced vertex.
#pragma once

#include <vector>

#include "ops/sequence.h"

namespace opgraph {

struct AffineTail {
  struct Term {
    int vertex;              // cage vertex v
    Eigen::Matrix3d matrix;  // M_ov
  };
  Positions<double> offset;              // #O (the output of an all-zero cage)
  std::vector<std::vector<Term>> terms;  // #O, each sorted by vertex
  std::vector<Polygon> faces;            // the output topology
  int num_cage_vertices = 0;

  // #O output positions of the cage positions `cage` (#V).
  Positions<double> Apply(const Positions<double>& cage) const;
};

// Ops [first_op, end) of `sequence`, prepared on the topology of `cage` (their input step: run
// EvaluateSequence first), probed one cage coordinate at a time. Throws std::runtime_error
// when the ops do not map `cage` to the sequence's output as probed (an op that is not affine
// in its input positions).
AffineTail ProbeAffineTail(const Sequence& sequence, int first_op, const Mesh& cage, const Mesh& output);

}  // namespace opgraph
