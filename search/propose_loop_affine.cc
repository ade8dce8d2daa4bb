// Loop moves and tilts (search/proposals.h).
#include <algorithm>
#include <cmath>

#include "search/layout.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

// The residual samples (outside and inside) on faces whose centroid lies within `reach` of
// `position` along `axis`.
size_t ResidualNear(const FaceResiduals& residuals, int axis, double position, double reach) {
  size_t count = 0;
  for (size_t f = 0; f < residuals.centroids.size(); ++f) {
    if (std::abs(residuals.centroids[f][axis] - position) <= reach) {
      count += residuals.outside[f].size() + residuals.inside[f].size();
    }
  }
  return count;
}

// Removes `op` (a loop scale of the profile) from `layout`'s profile; false when it has none.
bool RemoveFromProfile(Layout* layout, const Json& op) {
  const auto found = std::find(layout->profile.begin(), layout->profile.end(), op);
  if (found == layout->profile.end()) return false;
  layout->profile.erase(found);
  return true;
}

// Where a loop's tilt starts: a tilt about an axis in the loop's plane slides the loop's
// vertices along the box's faces, which leaves the surface unchanged to first order, so a fit
// from no tilt stays there; it starts at kTiltStartDeg either way about either axis.
constexpr double kTiltStartDeg = 12;
std::vector<Vec3d> TiltStarts(int axis) {
  std::vector<Vec3d> starts;
  for (int about = 0; about < 3; ++about) {
    if (about == axis) continue;
    for (const double sign : {1.0, -1.0}) starts.push_back(sign * kTiltStartDeg * Vec3d::Unit(about));
  }
  return starts;
}

std::string StartName(const Vec3d& start) {
  for (int a = 0; a < 3; ++a) {
    if (start[a] != 0) return std::string(" (from ") + (start[a] > 0 ? "+" : "-") + "XYZ"[a] + ")";
  }
  return "";
}

// A rotation of the profile's loop group `verts` (a box along `axis` on the 2x2x2 cube), from
// `rotation_deg`, put first after the cage's scale: a rotation does not commute with an unequal
// scale, so a loop tilted on the scaled shape (a modeller's tilt) is not a rotation before it.
// False when ops after the scale (a ridge, a deformation, a grid across the loop) move or add the
// loop's vertices.
bool AddRotateAfterScale(Layout* layout, build::VertexTarget verts, int axis, const Vec3d& rotation_deg) {
  if (!layout->ridge.empty() || !layout->deforms.empty() || !layout->grid.empty()) return false;
  if (!verts.box.lo[axis] || !verts.box.hi[axis]) return false;
  const double scale = layout->scale["params"]["scale"][axis].get<double>();
  verts.box.lo[axis] = *verts.box.lo[axis] * scale;
  verts.box.hi[axis] = *verts.box.hi[axis] * scale;
  if (scale < 0) std::swap(verts.box.lo[axis], verts.box.hi[axis]);
  layout->details.insert(layout->details.begin(), build::EdgeLoopRotate(verts, rotation_deg));
  return true;
}

// A shift and four tilts of the loop group `verts` (along `axis`, the `rank`-th nearest the
// residual): in place of the profile's loop scale `replaced`, or beside it when that is null.
// A shift joins the profile (it acts before the cage's scale, which it commutes with;
// scale_first.h maps it); a tilt acts after the scale (AddRotateAfterScale).
Round LoopMoveRound(const build::VertexTarget& verts, int axis, size_t rank, const Json& replaced) {
  const std::string which = " on the loop group " + std::to_string(rank + 1) + " nearest the residual";
  const std::string change = replaced.is_null() ? "+" : "EdgeLoopAffineScale -> ";
  // The scale out of the profile (or nothing to remove); false when the layout has no such profile.
  auto prepare = [replaced](Layout* l) {
    return replaced.is_null() ? !l->profile.empty() : RemoveFromProfile(l, replaced);
  };
  Round round;
  round.alternatives.push_back([=](Layout* l) -> std::string {
    if (!prepare(l)) return "";
    l->profile.push_back(build::EdgeLoopTranslate(verts, Vec3d::Zero()));
    return change + "EdgeLoopAffineTranslate" + which;
  });
  for (const Vec3d& start : TiltStarts(axis)) {
    round.alternatives.push_back([=](Layout* l) -> std::string {
      if (!prepare(l) || !AddRotateAfterScale(l, verts, axis, start)) return "";
      return change + "EdgeLoopAffineRotate" + which + StartName(start);
    });
  }
  return round;
}

}  // namespace

std::vector<Round> ProposeLoopMoves(const Layout& best, const FaceResiduals& residuals) {
  struct Loop {
    build::VertexTarget verts;
    int axis;
    size_t residual;
    size_t index;  // of its scale in the profile
  };
  // The profile's loop groups: the boxes of its loop scales, along the profile's cut axis.
  std::vector<Loop> loops;
  const Json* cut = nullptr;
  for (size_t index = 0; index < best.profile.size(); ++index) {
    const Json& op = best.profile[index];
    if (op["op"] == "LoopCut") cut = &op;
    if (op["op"] != "EdgeLoopAffineScale" || cut == nullptr) continue;
    const Json& box = op["params"]["verts"]["box"];
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (!box[0][a].is_null()) axis = a;
    }
    if (axis < 0) continue;
    Loop loop{{Box::Parse(box, "box"), op["params"]["verts"].value("expect", -1)}, axis, 0, index};
    // The cage is scaled after the profile: the loop's position in the cage's frame.
    const double scale = best.scale["params"]["scale"][axis].get<double>();
    const double lo = box[0][axis].get<double>() * scale, hi = box[1][axis].get<double>() * scale;
    loop.residual = ResidualNear(residuals, axis, 0.5 * (lo + hi), 0.5 * (hi - lo) + 0.25 * std::abs(scale));
    loops.push_back(loop);
  }
  std::stable_sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.residual > b.residual; });
  std::vector<Round> rounds;
  // A loop tilted or shifted rather than scaled: the scale replaced (no op added), on the two
  // loop groups with the most residual. Tried even where no residual sample stands out: a scale
  // imitates a slight tilt to within the sampling, and only the fit tells them apart.
  for (size_t i = 0; i < loops.size() && i < 2; ++i) {
    rounds.push_back(LoopMoveRound(loops[i].verts, loops[i].axis, i, best.profile[loops[i].index]));
  }
  // Then either beside the scale, where the residual calls for more.
  for (size_t i = 0; i < loops.size() && i < 2 && loops[i].residual > 0; ++i) {
    rounds.push_back(LoopMoveRound(loops[i].verts, loops[i].axis, i, nullptr));
  }
  return rounds;
}

}  // namespace opgraph
