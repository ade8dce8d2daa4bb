#include "search/layout.h"

#include <cmath>

#include "ops/builders.h"

namespace opgraph {
namespace {

// A loop lies in a plane across its cut axis, so scaling along that axis about the loop's
// median does nothing; the fit leaves it drifting (to 1e4 and more), and Blender's float
// coordinates would turn that into real offsets. Pin it to 1 where the box holds one loop
// (narrower than the cut spacing); for several loops it spaces them and is kept.
void PinFlatLoopScales(std::vector<Json>* part) {
  double spacing = 0;
  for (Json& op : *part) {
    if (op["op"] == "LoopCut") spacing = 2.0 / (op["params"]["cuts"].get<double>() + 1);
    if (op["op"] != "EdgeLoopAffineScale") continue;
    const Json& box = op["params"]["verts"]["box"];
    for (int axis = 0; axis < 3; ++axis) {
      if (box[0][axis].is_null()) continue;
      if (box[1][axis].get<double>() - box[0][axis].get<double>() < spacing) op["params"]["scale"][axis] = 1.0;
    }
  }
}

}  // namespace

int Layout::NumOps() const {
  return CageStep() + 1 + (rotate.is_null() ? 0 : 1) + (translate.is_null() ? 0 : 1) + (mirror_axes.empty() ? 0 : 2) +
         (subdivide ? 1 : 0);
}

int Layout::CageStep() const {
  return static_cast<int>(profile.size() + grid.size() + ridge.size() + deforms.size() + details.size());
}

bool Layout::HasDetail(const std::string& op_name) const {
  for (const Json& op : details) {
    if (op["op"] == op_name) return true;
  }
  return false;
}

Vec3d Layout::LocalToCage(Vec3d local) const {
  if (mirror_axes.empty()) return local;
  const Json& offset = mirror_offset["params"]["offset"];
  for (int axis : mirror_axes) local[axis] = std::copysign(std::abs(local[axis]), offset[axis].get<double>());
  return local - Vec3d(offset[0], offset[1], offset[2]);
}

Eigen::Matrix3d Layout::PoseRotation() const {
  if (rotate.is_null()) return Eigen::Matrix3d::Identity();
  const Json& degrees = rotate["params"]["rotation_deg"];
  return EulerXYZToMatrix(DegToRad(degrees[0].get<double>()), DegToRad(degrees[1].get<double>()),
                          DegToRad(degrees[2].get<double>()));
}

Vec3d Layout::PoseTranslation() const {
  if (translate.is_null()) return Vec3d::Zero();
  const Json& offset = translate["params"]["offset"];
  return Vec3d(offset[0], offset[1], offset[2]);
}

Json Layout::Document() const {
  std::vector<Json> ops;
  for (const std::vector<Json>* part : {&profile, &grid}) ops.insert(ops.end(), part->begin(), part->end());
  ops.push_back(scale);
  for (const std::vector<Json>* part : {&ridge, &deforms, &details}) ops.insert(ops.end(), part->begin(), part->end());
  if (!mirror_axes.empty()) {
    std::vector<build::Axis> axes;
    for (int axis : mirror_axes) axes.push_back(static_cast<build::Axis>(axis));
    ops.push_back(mirror_offset);
    ops.push_back(build::Mirror(axes));
  }
  if (subdivide) ops.push_back(build::Subdivision(2));
  if (!rotate.is_null()) ops.push_back(rotate);
  if (!translate.is_null()) ops.push_back(translate);
  return build::Document(ops);
}

Layout Layout::WithParameters(const Json& fitted) const {
  const Json& ops = fitted.at("operations");
  Layout out = *this;
  size_t i = 0;
  for (Json& op : out.profile) op = ops[i++];
  for (Json& op : out.grid) op = ops[i++];
  PinFlatLoopScales(&out.profile);
  PinFlatLoopScales(&out.grid);
  out.scale = ops[i++];
  for (std::vector<Json>* part : {&out.ridge, &out.deforms, &out.details}) {
    for (Json& op : *part) op = ops[i++];
  }
  if (!mirror_axes.empty()) out.mirror_offset = ops[i], i += 2;
  if (subdivide) ++i;
  if (!rotate.is_null()) out.rotate = ops[i++];
  if (!translate.is_null()) out.translate = ops[i++];
  return out;
}

}  // namespace opgraph
