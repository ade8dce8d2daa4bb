#include "ops/sequence_op_names.h"

namespace opgraph {

std::vector<std::string> SequenceOpNames(const Json& document) {
  std::vector<std::string> names;
  for (const Json& op : document.at("operations")) names.push_back(op.at("op"));
  return names;
}

}  // namespace opgraph
