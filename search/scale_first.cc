#include "search/scale_first.h"

#include <string>

namespace opgraph {
namespace {

Json ScalePoint(const Json& point, const Json& scale) {
  Json out = point;
  for (int axis = 0; axis < 3; ++axis) {
    if (!point[axis].is_null()) out[axis] = point[axis].get<double>() * scale[axis].get<double>();
  }
  return out;
}

}  // namespace

Json ScaleFirst(const Json& document) {
  const Json& ops = document.at("operations");
  size_t scale_index = 0;
  while (scale_index < ops.size() && ops[scale_index].at("op") != "GlobalAffineScale") {
    const std::string name = ops[scale_index].at("op");
    if (name != "LoopCut" && name != "EdgeLoopAffineScale" && name != "EdgeLoopAffineTranslate") return document;
    ++scale_index;
  }
  if (scale_index == 0 || scale_index == ops.size()) return document;
  const Json& scale = ops[scale_index].at("params").at("scale");
  for (const Json& s : scale) {
    if (!(s.get<double>() > 0)) return document;  // a mirroring scale would swap box bounds
  }
  Json out = document;
  Json& moved = out["operations"];
  moved = Json::array({ops[scale_index]});
  for (size_t k = 0; k < ops.size(); ++k) {
    if (k == scale_index) continue;
    Json op = ops[k];
    if (k < scale_index) {
      Json& params = op["params"];
      if (op["op"] == "LoopCut") {
        params["near"] = ScalePoint(params.value("near", Json::array({0.0, 0.0, 0.0})), scale);
      } else {
        if (!params.at("verts").contains("box")) return document;  // explicit indices stay as they are
        for (Json& corner : params["verts"]["box"]) corner = ScalePoint(corner, scale);
        if (op["op"] == "EdgeLoopAffineTranslate") params["offset"] = ScalePoint(params.at("offset"), scale);
      }
    }
    moved.push_back(op);
  }
  return out;
}

}  // namespace opgraph
