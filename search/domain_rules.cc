#include "search/domain_rules.h"

#include <limits>
#include <stdexcept>

#include "core/geometry.h"
#include "ops/op.h"

namespace opgraph {
namespace {

// Index of `op`'s parameter `name` in its fitted parameter block.
int ParamIndex(const Json& op, const std::string& name) {
  const std::unique_ptr<Op> created = CreateOp(op.at("op"), op.at("params"));
  const std::vector<ParamSpec>& specs = created->specs();
  for (int i = 0; i < static_cast<int>(specs.size()); ++i) {
    if (specs[i].name == name) return i;
  }
  throw std::logic_error(op.at("op").get<std::string>() + " has no parameter " + name);
}

}  // namespace

FitterOptions WithDomainRules(FitterOptions options, const Json& document, const Vec3d& half_extent) {
  const double min_half_extent = half_extent.minCoeff();
  constexpr double kMaxTilt = kPi / 4;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Json& ops = document.at("operations");
  for (int k = 0; k < static_cast<int>(ops.size()); ++k) {
    if (ops[k].at("op") == "Extrude") {
      for (const char* tilt : {"tilt_u", "tilt_v"}) {
        options.domain_rules.push_back({k, ParamIndex(ops[k], tilt), -kMaxTilt, kMaxTilt, 1.0});
      }
      options.domain_rules.push_back({k, ParamIndex(ops[k], "width"), 0.1, 10.0, 1.0});
    }
    // A flat target (a sheet: its box under 1% as thick as it is long) would squash the cube to
    // nothing, an edge Blender's float32 coordinates cannot keep. Only there: any other target's
    // fits stay exactly as they were.
    if (ops[k].at("op") == "GlobalAffineScale" && half_extent.minCoeff() < 0.01 * half_extent.maxCoeff()) {
      for (const char* axis : {"scale_x", "scale_y", "scale_z"}) {
        options.domain_rules.push_back({k, ParamIndex(ops[k], axis), 1e-3 * half_extent.maxCoeff(), kInf, 1.0});
      }
    }
    // A cutter grown far beyond the shape changes nothing the fit sees (past the shape its length
    // is free), but Blender keeps its corners in float32, and the rounding at 500 times the
    // shape's size moved the cut 4e-6 of the diagonal (a mug's bore, from a point cloud).
    if (ops[k].at("op") == "Boolean") {
      for (const char* axis : {"size_x", "size_y", "size_z"}) {
        options.domain_rules.push_back({k, ParamIndex(ops[k], axis), 0.0, kMaxBooleanSize * half_extent.maxCoeff(), 1.0});
      }
    }
    if (ops[k].at("op") == "Inset") {
      options.domain_rules.push_back({k, ParamIndex(ops[k], "thickness"), 0.01 * min_half_extent, kInf, 1.0});
    }
  }
  return options;
}

}  // namespace opgraph
