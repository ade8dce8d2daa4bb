// The op names of a sequence document, in order (what LCS and the replay guards compare).
#pragma once

#include <string>
#include <vector>

#include "ops/params.h"

namespace opgraph {

// "operations"[i]["op"] for each i; throws the JSON library's error when a field is missing.
std::vector<std::string> SequenceOpNames(const Json& document);

}  // namespace opgraph
