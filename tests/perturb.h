// Seeded perturbation of a program's fitted parameters, shared by the recovery test and the
// benchmarks: angles by +-0.3 rad, other parameters by +-30 % (of 0.1 for zero values), kept
// inside the bounds.
#pragma once

#include <cstdint>

#include "program/program.h"

namespace opgraph {

// Returns the number of perturbed parameters.
int PerturbParameters(const Program& program, const Sequence& sequence, uint64_t seed);

}  // namespace opgraph
