// A sequence in the search's fixed layout. During the search ops act in the cube's own frame,
// so element selectors stay valid while the fit moves the global pose:
//   cube -> profile (loop cuts, loop scales) -> grid (loop cuts, loop scales) -> Scale
//   -> ridge -> deformations -> details (extrusions, insets, booleans, bevel)
//   -> [Translate, Mirror] -> Subdivision -> Rotate -> Translate.
// Each part is a list of op entries built by ops/builders.h; splitting a fitted document back
// into parts relies on fits keeping the op count.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "ops/params.h"

namespace opgraph {

struct Layout {
  std::vector<Json> profile;  // on the 2x2x2 cube: loop cuts along one axis, loop scales
  std::string profile_name;   // which profile proposal `profile` is, empty when none
  std::vector<Json> grid;     // then: loop cuts across the other axes, loop scales
  // `rotate` and `translate` are null when the pose has none (the search may drop a Rotate or
  // Translate that does not pay for itself: search/propose_pose.cc).
  Json scale, rotate, translate;
  std::vector<Json> ridge;    // after the scale: a loop cut with its top vertices raised
  std::vector<Json> deforms;
  std::vector<Json> details;  // extrusions (and their insets), booleans, a bevel
  // A mirrored pair (a symmetric target in two parts): the cage is built on one part, moved by
  // `mirror_offset` (a GlobalAffineTranslate in the cube's frame) and mirrored about the cube's
  // origin along `mirror_axes`.
  std::vector<int> mirror_axes;
  Json mirror_offset;
  bool subdivide = false;
  // The frame of the pose this layout was placed in: the cube's half extents on the target's
  // box, and the box's axes in world coordinates (columns).
  Vec3d half_extent = Vec3d::Ones();
  Eigen::Matrix3d world_from_local = Eigen::Matrix3d::Identity();

  int NumOps() const;
  // Index of the last op before Subdivision / Rotate: the step whose mesh is the cage.
  int CageStep() const;
  bool HasDetail(const std::string& op_name) const;
  // `local` (a point in the frame of the pose's Rotate and Translate) in the cage's frame: for a
  // mirrored pair, folded onto the built part and moved back by the offset.
  Vec3d LocalToCage(Vec3d local) const;
  // The pose's Rotate and Translate (identity where dropped): world = rotation * local + translation.
  Eigen::Matrix3d PoseRotation() const;
  Vec3d PoseTranslation() const;
  Json Document() const;
  // This layout with the parameters of `fitted` (a fit of Document()).
  Layout WithParameters(const Json& fitted) const;
};

// A layout fitted to the target: its data loss, and whether the fit succeeded and replays.
struct Trial {
  Layout layout;
  double loss = std::numeric_limits<double>::infinity();
  bool ok = false;
};

}  // namespace opgraph
