// The size limits of a sequence's evaluation, in a header of their own so the tools' command
// lines (apps/cli_flags.h) state them without the ops' dependencies.
#pragma once

#include <cstdint>

namespace opgraph {

// The most faces a step of a sequence may output unless told otherwise (Sequence::max_faces,
// the tools' --max-faces), and the most it may be told: beyond them a sequence (20
// Subdivisions, each in range) would exhaust memory before it fails.
constexpr int64_t kDefaultMaxFaces = 2000000;
constexpr int64_t kMaxFacesCeiling = 20000000;

}  // namespace opgraph
