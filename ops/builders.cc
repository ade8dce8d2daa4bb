#include "ops/builders.h"

#include "ops/sequence.h"

namespace opgraph {
namespace build {
namespace {

Json Entry(const char* name, Json params) { return {{"op", name}, {"params", std::move(params)}}; }

Json Points(const std::vector<Vec3d>& points) {
  Json list = Json::array();
  for (const Vec3d& p : points) list.push_back(opgraph::ToJson(p));
  return list;
}

const char* DeformName(Deform kind) {
  switch (kind) {
    case Deform::kTwist: return "SimpleDeformTwist";
    case Deform::kBend: return "SimpleDeformBend";
    case Deform::kTaper: return "SimpleDeformTaper";
    case Deform::kStretch: return "SimpleDeformStretch";
  }
  return "";
}

}  // namespace

std::string AxisName(Axis axis) { return axis == Axis::kX ? "X" : axis == Axis::kY ? "Y" : "Z"; }
Axis AxisNamed(const std::string& name) { return name == "X" ? Axis::kX : name == "Y" ? Axis::kY : Axis::kZ; }

Vec3d AxisVector(Axis axis) { return Vec3d::Unit(static_cast<int>(axis)); }

Json FaceTarget::ToJson() const {
  Json json = Json::object();
  if (normals.size() == 1) json["normal"] = opgraph::ToJson(normals[0]);
  if (normals.size() > 1) json["normal_any"] = Points(normals);
  if (min_dot != 0.99) json["min_dot"] = min_dot;
  if (box.Bounded()) json["box"] = box.ToJson();
  if (!centers.empty()) json["centers"] = Points(centers);
  if (expect >= 0) json["expect"] = expect;
  return json;
}

Json VertexTarget::ToJson() const {
  Json json = {{"box", box.ToJson()}};
  if (expect >= 0) json["expect"] = expect;
  return json;
}

Json GlobalScale(const Vec3d& scale) { return Entry("GlobalAffineScale", {{"scale", opgraph::ToJson(scale)}}); }
Json GlobalRotate(const Vec3d& rotation_deg) {
  return Entry("GlobalAffineRotate", {{"rotation_deg", opgraph::ToJson(rotation_deg)}});
}
Json GlobalTranslate(const Vec3d& offset) { return Entry("GlobalAffineTranslate", {{"offset", opgraph::ToJson(offset)}}); }

Json SimpleDeform(Deform kind, Axis axis, double amount, double limit_lo, double limit_hi) {
  const bool angular = kind == Deform::kTwist || kind == Deform::kBend;
  Json params = {{"axis", AxisName(axis)}, {angular ? "angle_deg" : "factor", amount}};
  if (limit_lo != 0 || limit_hi != 1) params["limits"] = {limit_lo, limit_hi};
  return Entry(DeformName(kind), params);
}

Json Subdivision(int levels) { return Entry("Subdivision", {{"levels", levels}}); }

Json Mirror(const std::vector<Axis>& axes) {
  Json names = Json::array();
  for (Axis axis : axes) names.push_back(AxisName(axis));
  return Entry("Mirror", {{"axes", names}});
}

Json LoopCut(Axis axis, int cuts, const Vec3d& near) {
  return Entry("LoopCut", {{"axis", AxisName(axis)}, {"cuts", cuts}, {"near", opgraph::ToJson(near)}});
}

Json KnifeEdges(const FaceTarget& face, const Vec3d& edge_point_a, const Vec3d& edge_point_b) {
  return Entry("KnifeCut", {{"face", face.ToJson()}, {"edge_points", Points({edge_point_a, edge_point_b})}});
}

Json KnifePlane(const Vec3d& plane_co, const Vec3d& plane_no) {
  return Entry("KnifeCut", {{"plane_co", opgraph::ToJson(plane_co)}, {"plane_no", opgraph::ToJson(plane_no)}});
}

Json Extrude(const ExtrudeArgs& args) {
  Json params = {{"faces", args.faces.ToJson()}, {"height", args.height}};
  if (args.individual) params["mode"] = "individual";
  if (args.width != 1) params["width"] = args.width;
  if (args.tilt_deg[0] != 0 || args.tilt_deg[1] != 0) params["tilt_deg"] = {args.tilt_deg[0], args.tilt_deg[1]};
  return Entry("Extrude", params);
}

Json Inset(const FaceTarget& faces, double thickness, double depth) {
  Json params = {{"faces", faces.ToJson()}, {"thickness", thickness}};
  if (depth != 0) params["depth"] = depth;
  return Entry("Inset", params);
}

Json EdgeLoopScale(const VertexTarget& verts, const Vec3d& scale) {
  return Entry("EdgeLoopAffineScale", {{"verts", verts.ToJson()}, {"scale", opgraph::ToJson(scale)}});
}
Json EdgeLoopRotate(const VertexTarget& verts, const Vec3d& rotation_deg) {
  return Entry("EdgeLoopAffineRotate", {{"verts", verts.ToJson()}, {"rotation_deg", opgraph::ToJson(rotation_deg)}});
}
Json EdgeLoopTranslate(const VertexTarget& verts, const Vec3d& offset) {
  return Entry("EdgeLoopAffineTranslate", {{"verts", verts.ToJson()}, {"offset", opgraph::ToJson(offset)}});
}

Json VertexDisplace(const std::vector<DisplaceGroup>& groups) {
  Json list = Json::array();
  for (const DisplaceGroup& g : groups) list.push_back({{"verts", g.verts.ToJson()}, {"offset", opgraph::ToJson(g.offset)}});
  return Entry("VertexDisplace", {{"groups", list}});
}

Json Bevel(double width, int segments, double angle_limit_deg) {
  Json params = {{"width", width}, {"segments", segments}};
  if (angle_limit_deg >= 0) params["limit_method"] = "ANGLE", params["angle_limit_deg"] = angle_limit_deg;
  return Entry("Bevel", params);
}

std::string PrimitiveName(Primitive primitive) {
  switch (primitive) {
    case Primitive::kCube: return "cube";
    case Primitive::kPrism6: return "prism6";
    case Primitive::kPrism8: return "prism8";
    case Primitive::kCylinder: return "cylinder";
  }
  return "";
}

Json Boolean(const BooleanArgs& args) {
  return Entry("Boolean", {{"operation", args.difference ? "DIFFERENCE" : "UNION"},
                           {"primitive", PrimitiveName(args.primitive)},
                           {"size", opgraph::ToJson(args.size)},
                           {"rotation_deg", opgraph::ToJson(args.rotation_deg)},
                           {"location", opgraph::ToJson(args.location)}});
}

Json Document(const std::vector<Json>& operations) {
  return {{"format", "opgraph-sequence"},
          {"version", kSequenceFormatVersion},
          {"start", {{"primitive", "cube"}, {"size", 2.0}}},
          {"operations", operations}};
}

}  // namespace build
}  // namespace opgraph
