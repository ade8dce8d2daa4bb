// The table of implemented operations: canonical name -> factory.
#include <functional>
#include <map>
#include <stdexcept>

#include "core/printable.h"
#include "ops/boolean.h"
#include "ops/bevel.h"
#include "ops/global_affine.h"
#include "ops/inset.h"
#include "ops/knife_cut.h"
#include "ops/loop_cut.h"
#include "ops/edge_loop_affine.h"
#include "ops/extrude.h"
#include "ops/mirror.h"
#include "ops/op.h"
#include "ops/vertex_displace.h"
#include "ops/subdivision.h"
#include "ops/simple_deform.h"

namespace opgraph {
namespace {

using Factory = std::function<std::unique_ptr<Op>(const Json&)>;

const std::map<std::string, Factory>& Factories() {
  static const std::map<std::string, Factory> factories = {
      {"GlobalAffineRotate",
       [](const Json& p) { return std::make_unique<GlobalAffineOp>(GlobalAffineOp::Kind::kRotate, p); }},
      {"GlobalAffineScale",
       [](const Json& p) { return std::make_unique<GlobalAffineOp>(GlobalAffineOp::Kind::kScale, p); }},
      {"Subdivision", [](const Json& p) { return std::make_unique<SubdivisionOp>(p); }},
      {"LoopCut", [](const Json& p) { return std::make_unique<LoopCutOp>(p); }},
      {"GlobalAffineTranslate",
       [](const Json& p) { return std::make_unique<GlobalAffineOp>(GlobalAffineOp::Kind::kTranslate, p); }},
      {"SimpleDeformTwist",
       [](const Json& p) { return std::make_unique<SimpleDeformOp>(SimpleDeformOp::Mode::kTwist, p); }},
      {"SimpleDeformBend",
       [](const Json& p) { return std::make_unique<SimpleDeformOp>(SimpleDeformOp::Mode::kBend, p); }},
      {"SimpleDeformTaper",
       [](const Json& p) { return std::make_unique<SimpleDeformOp>(SimpleDeformOp::Mode::kTaper, p); }},
      {"SimpleDeformStretch",
       [](const Json& p) { return std::make_unique<SimpleDeformOp>(SimpleDeformOp::Mode::kStretch, p); }},
      {"VertexDisplace", [](const Json& p) { return std::make_unique<VertexDisplaceOp>(p); }},
      {"EdgeLoopAffineRotate",
       [](const Json& p) { return std::make_unique<EdgeLoopAffineOp>(EdgeLoopAffineOp::Kind::kRotate, p); }},
      {"EdgeLoopAffineScale",
       [](const Json& p) { return std::make_unique<EdgeLoopAffineOp>(EdgeLoopAffineOp::Kind::kScale, p); }},
      {"EdgeLoopAffineTranslate",
       [](const Json& p) { return std::make_unique<EdgeLoopAffineOp>(EdgeLoopAffineOp::Kind::kTranslate, p); }},
      {"Mirror", [](const Json& p) { return std::make_unique<MirrorOp>(p); }},
      {"Extrude", [](const Json& p) { return std::make_unique<ExtrudeOp>(p); }},
      {"Inset", [](const Json& p) { return std::make_unique<InsetOp>(p); }},
      {"KnifeCut", [](const Json& p) { return std::make_unique<KnifeCutOp>(p); }},
      {"Boolean", [](const Json& p) { return std::make_unique<BooleanOp>(p); }},
      {"Bevel", [](const Json& p) { return std::make_unique<BevelOp>(p); }},
  };
  return factories;
}

}  // namespace

std::unique_ptr<Op> CreateOp(const std::string& name, const Json& params) {
  const auto it = Factories().find(name);
  if (it == Factories().end()) throw std::invalid_argument("unknown op '" + Printable(name) + "'");
  return it->second(params);
}

std::vector<std::string> OpNames() {
  std::vector<std::string> names;
  for (const auto& entry : Factories()) names.push_back(entry.first);
  return names;
}

}  // namespace opgraph
