#include "tests/gt_convert.h"

#include <algorithm>
#include <fstream>

#include "ops/op.h"

namespace opgraph {

Json ConvertGtSequence(const std::filesystem::path& path, std::string* why_not) {
  std::ifstream in(path);
  const Json gt = Json::parse(in);
  const std::vector<std::string> implemented = OpNames();
  Json operations = Json::array();
  for (const Json& entry : gt.at("operations")) {
    const std::string name = entry.at("op");
    const Json& p = entry.at("params");
    if (std::find(implemented.begin(), implemented.end(), name) == implemented.end()) {
      *why_not = "op " + name + " not implemented yet";
      return nullptr;
    }
    Json params;
    if (name == "GlobalAffineScale" || name == "GlobalAffineRotate" || name == "GlobalAffineTranslate") {
      if (p.contains("pivot") && p["pivot"] != Json::array({0.0, 0.0, 0.0})) {
        *why_not = name + " about a pivot other than the origin";
        return nullptr;
      }
      if (name == "GlobalAffineScale") params = {{"scale", p.at("scale")}};
      if (name == "GlobalAffineRotate") params = {{"rotation_deg", p.at("rotation_deg")}};
      if (name == "GlobalAffineTranslate") params = {{"offset", p.at("offset")}};
    } else if (name == "Subdivision") {
      if (p.value("type", std::string("CATMULL_CLARK")) != "CATMULL_CLARK" ||
          !p.value("use_limit_surface", true) || p.value("boundary_smooth", std::string("ALL")) != "ALL") {
        *why_not = "Subdivision other than Catmull-Clark with limit surface and boundary_smooth ALL";
        return nullptr;
      }
      params = {{"levels", p.at("levels")}};
    } else if (name == "Extrude") {
      params = {{"faces", p.at("faces")}, {"height", p.at("height")}, {"mode", p.value("mode", "region")}};
    } else if (name == "Inset") {
      if (p.value("mode", "region") != "region" || !p.value("use_even_offset", true)) {
        *why_not = "Inset other than region mode with even offset";
        return nullptr;
      }
      params = {{"faces", p.at("faces")}, {"thickness", p.at("thickness")}, {"depth", p.value("depth", 0.0)}};
    } else if (name.rfind("SimpleDeform", 0) == 0) {
      if (p.value("origin", Json::array({0.0, 0.0, 0.0})) != Json::array({0.0, 0.0, 0.0}) ||
          p.value("lock", Json::array({false, false, false})) != Json::array({false, false, false})) {
        *why_not = name + " with an origin object or locked axes";
        return nullptr;
      }
      params = {{"axis", p.at("axis")}, {"limits", p.value("limits", Json::array({0.0, 1.0}))}};
      if (p.contains("angle_deg")) params["angle_deg"] = p["angle_deg"];
      if (p.contains("factor")) params["factor"] = p["factor"];
    } else if (name == "Mirror") {
      params["axes"] = p.at("axes");
    } else if (name == "VertexDisplace") {
      params["groups"] = Json::array();
      for (const Json& g : p.at("groups")) params["groups"].push_back({{"verts", g.at("verts")}, {"offset", g.at("offset")}});
    } else if (name.rfind("EdgeLoopAffine", 0) == 0) {
      if (p.value("pivot", "median") != "median") {
        *why_not = name + " about a pivot other than the median";
        return nullptr;
      }
      params["verts"] = p.at("verts");
      for (const char* key : {"scale", "rotation_deg", "offset"}) {
        if (p.contains(key)) params[key] = p.at(key);
      }
    } else if (name == "LoopCut") {
      params = {{"axis", p.at("axis")}, {"cuts", p.at("cuts")},
                {"near", p.value("near", Json::array({0.0, 0.0, 0.0}))}};
    } else if (name == "KnifeCut" && p.contains("plane_co")) {
      params = {{"plane_co", p.at("plane_co")}, {"plane_no", p.at("plane_no")}};
    } else if (name == "Boolean") {
      const Json& prim = p.at("primitive");
      const std::string type = prim.at("type");
      if (p.value("solver", "EXACT") != "EXACT" || p.value("use_self", false) || p.value("use_hole_tolerant", false)) {
        *why_not = "Boolean other than the EXACT solver without self intersection and hole tolerance";
        return nullptr;
      }
      const int segments = type == "prism6" ? 6 : type == "prism8" ? 8 : 32;
      if (type != "cube" && prim.value("segments", segments) != segments) {
        *why_not = "Boolean " + type + " with " + std::to_string(prim["segments"].get<int>()) + " segments";
        return nullptr;
      }
      Json size = prim.value("size", Json());
      if (type != "cube") {
        const double diameter = 2 * prim.at("radius").get<double>();
        size = Json::array({diameter, diameter, prim.at("depth")});
      }
      params = {{"operation", p.at("operation")}, {"primitive", type}, {"size", size},
                {"rotation_deg", prim.value("rotation_deg", Json::array({0.0, 0.0, 0.0}))},
                {"location", prim.value("location", Json::array({0.0, 0.0, 0.0}))}};
    } else {
      *why_not = "no converter for " + name + " yet";
      return nullptr;
    }
    operations.push_back({{"op", name}, {"params", params}});
  }
  return {{"version", 1}, {"start", {{"primitive", "cube"}, {"size", 2.0}}}, {"operations", operations}};
}

}  // namespace opgraph
