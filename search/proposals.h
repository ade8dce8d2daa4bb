// Proposal families: each a function from the current best layout (and, where it needs one, an
// analysis of the target or of the residuals) to changes for the policy to judge. No fitting,
// pricing or logging here: the dependency runs one way, from the policy to the proposals.
// One family per file (propose_<family>.cc).
#pragma once

#include <string>
#include <vector>

#include "ops/builders.h"
#include "search/face_residuals.h"
#include "search/layout.h"
#include "search/policy.h"
#include "search/residual_clusters.h"
#include "solver/target.h"

namespace opgraph {

// Subdivision (level 2) at the end of the structure.
std::vector<Round> ProposeSmoothing(const Layout& best);

// The axes a profile is proposed along: the long axis, and the axis across which the section
// changes most on all sides at once (`section_changes`, search/section_changes.h) when it
// clearly does: a vase or a waisted box need not be longest along their profile.
std::vector<int> ProfileAxes(const Layout& best, const Vec3d& section_changes);

// Profiles along ProfileAxes (alternatives of one decision), simplest first: a waist or bulge (two loops scaled together),
// a pinch between two end sections (the inner two of four), the end loops apart, then one
// scale per loop; each also with Subdivision (a round form, a barrel or a vase, is a profile
// on a subdivided cage, and neither alone lowers the loss much). A richer profile replaces a
// simpler one only when it pays for its extra ops.
std::vector<Round> ProposeProfiles(const Layout& best, const Vec3d& section_changes);

// Stepped or tilted profiles: a loop group's scale replaced by EdgeLoopAffineRotate or
// EdgeLoopAffineTranslate (the two groups with the most residual near them), then either added
// to them; a rotation from a tilt either way about either axis in the loop's plane.
std::vector<Round> ProposeLoopMoves(const Layout& best, const FaceResiduals& residuals);

// Twist, taper and stretch (along the long axis) and bend (about the others), from both sides
// of the identity, with rings along the long axis when there is no profile to bend smoothly.
std::vector<Round> ProposeDeforms(const Layout& best);

// The profile's loop count, as alternatives of one decision: a bare LoopCut (a twist's or a
// bend's rings) with each other count from 1 to 12, a profile with a scale per loop with each
// other count from 1 to 8, its scales resampled from the fitted ones. The fit picks the count
// (a twisted block's facets are where its loops are; a turned profile has as many loops as
// its steps).
std::vector<Round> ProposeLoopCounts(const Layout& best);

// A ridge or a peak (a gable roof): a loop cut across one axis, and the cut's vertices on one
// side of another axis raised along it; every axis pair and side, as alternatives.
std::vector<Round> ProposeRidges(const Layout& best);

// Holes through the shape (a ring, a handle's eye): a Boolean difference with a prism or a box
// through the centre along each axis; the fit sizes and places it.
std::vector<Round> ProposeHoles(const Layout& best);

// Holes and cuts placed by the residual (a slot, a notch, a bore, anywhere): a Boolean difference
// through each of the two largest `interior` clusters (FindResidualClusters: the target's
// surface inside the cage), along its thinnest and its longest axis, as a box in its principal
// frame, a cylinder, a prism of 6 or 8 sides, or a box square to the cage.
std::vector<Round> ProposeThroughHoles(const Layout& best, const std::vector<ResidualCluster>& interior);

// Rounded edges: Bevel on the edges sharper than 30 degrees with 5 segments (also instead of
// the extrusions, which can imitate a rounded rim), then the segment count.
std::vector<Round> ProposeBevels(const Layout& best);

// Protrusions and cavities from the residuals: Extrude (or Inset, then Extrude) on the cage
// faces with many target samples far outside or inside; faces wanting the same growth (a
// table's four legs) together first.
std::vector<Round> ProposeExtrusions(const Layout& best, const FaceResiduals& residuals);

// Boolean union (material the cage lacks) or difference (material it has in excess) with a box
// or a cylinder along each principal axis on the box of each of the four largest residual
// clusters, anywhere on the shape; at most three Booleans in a sequence, none after a Bevel.
std::vector<Round> ProposeBooleans(const Layout& best, const std::vector<ResidualCluster>& clusters);

// Shared by the Boolean and hole families: at most kMaxBooleans Booleans in a sequence, and
// primitives on the kMaxClusters largest residual clusters.
constexpr int kMaxBooleans = 3;
constexpr size_t kMaxClusters = 4;
int CountBooleans(const Layout& layout);
// A primitive on the cluster's box, its own +Z axis along the cluster's principal axis `axis`;
// a difference where the cluster is excess material, else a union.
build::BooleanArgs PrimitiveOnClusterBox(const ResidualCluster& cluster, build::Primitive primitive, int axis);

// Faceted solids: a bisecting KnifeCut across each axis with its new loop scaled (a faceted
// waist), and on the two quad faces with the most samples beyond them a KnifeCut between
// opposite edge midpoints with the new vertices raised (a ridge on a facet); none after a Bevel.
std::vector<Round> ProposeFacets(const Layout& best, const FaceResiduals& residuals);

// The sequence without its Rotate, its Translate, or both, refitted: a cage that the search
// tilted by a few degrees or moved a little to fit a shape it does not explain yet is simpler
// without them when the rest of the sequence can take their place.
std::vector<Round> ProposePoseDrops(const Layout& best);

// Loop-cut grids across two axes: faces where extrusions can start (legs at a table's corners).
// Each is judged with the extrusions it enables, so these are layouts to expand, not rounds.
struct Expansion {
  Layout layout;
  std::string what;
};
std::vector<Expansion> ProposeGrids(const Layout& best);

// The body of a table, a stool or a chair: the cube placed on the slab between the largest
// layers of the target's surface facing + and - along one axis, alone and with a loop-cut grid
// across it, and with a grid whose loops are where the parts beyond the slab start (a table's
// legs at its corners); for the two heaviest slabs (a chair's seat and its backrest). Empty
// when the target has no slab clearly thinner than its box.
std::vector<Expansion> ProposeSlabs(const Target& target, const Layout& pose);

// A box body (a limb's trunk, the block of an L or a T): along each axis of the pose's frame,
// the largest run of the target where its section is one constant rectangle (the sides of a
// box), at least a fifth of the box, with more beyond it; the cube on that run's box, for the
// extrusions that grow the rest from it (an Extrude's narrowed cap tapers, so the rest need not
// be boxes). Largest body first. Empty when no axis has one, or a part stands apart along it.
std::vector<Expansion> ProposeBoxBodies(const Target& target, const Layout& pose);

// A symmetric target in two parts (a pair of wings, of legs, of towers): the cube on the part
// beyond each symmetry plane of the pose's frame that has a gap around it, mirrored there.
// Empty when the target is not such a pair.
std::vector<Expansion> ProposeMirrors(const Target& target, const Layout& pose);

}  // namespace opgraph
