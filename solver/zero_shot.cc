#include "solver/zero_shot.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <tuple>
#include <set>
#include <sstream>

#include "core/geometry.h"
#include "core/metrics.h"
#include "core/surface_distance.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"
#include "solver/scale_first.h"

namespace opgraph {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kInf = std::numeric_limits<double>::infinity();
const char* const kAxisNames[3] = {"X", "Y", "Z"};

Json MakeOp(const std::string& name, Json params) { return {{"op", name}, {"params", std::move(params)}}; }

// A sequence in the controller's fixed layout (see zero_shot.h). Each part is a list of op
// documents; splitting a fitted document back into parts relies on fits keeping the op count.
struct Layout {
  std::vector<Json> profile;  // on the 2x2x2 cube: loop cuts along the long axis, loop scales
  std::string profile_name;   // which profile proposal `profile` is, empty when none
  std::vector<Json> grid;     // then: loop cuts across the other axes, loop scales
  Json scale, rotate, translate;
  std::vector<Json> ridge;    // after the scale: a loop cut with its top vertices raised
  std::vector<Json> deforms;
  std::vector<Json> details;  // extrusions (and their insets)
  bool subdivide = false;

  int NumOps() const {
    return static_cast<int>(profile.size() + grid.size() + ridge.size() + deforms.size() + details.size()) + 3 +
           (subdivide ? 1 : 0);
  }
  // Index of the last op before Subdivision / Rotate: the step whose mesh is the cage.
  int CageStep() const {
    return static_cast<int>(profile.size() + grid.size() + ridge.size() + deforms.size() + details.size());
  }

  Json Document() const {
    Json ops = Json::array();
    for (const Json& op : profile) ops.push_back(op);
    for (const Json& op : grid) ops.push_back(op);
    ops.push_back(scale);
    for (const Json& op : ridge) ops.push_back(op);
    for (const Json& op : deforms) ops.push_back(op);
    for (const Json& op : details) ops.push_back(op);
    if (subdivide) ops.push_back(MakeOp("Subdivision", {{"levels", 2}}));
    ops.push_back(rotate);
    ops.push_back(translate);
    return {{"version", kSequenceFormatVersion}, {"start", {{"primitive", "cube"}, {"size", 2.0}}}, {"operations", ops}};
  }

  // This layout with the parameters of `fitted` (a fit of Document()).
  Layout WithParameters(const Json& fitted) const {
    const Json& ops = fitted.at("operations");
    Layout out = *this;
    size_t i = 0;
    for (Json& op : out.profile) op = ops[i++];
    for (Json& op : out.grid) op = ops[i++];
    // A loop lies in a plane across its cut axis, so scaling along that axis about the loop's
    // median does nothing; the fit leaves it drifting (to 1e4 and more), and Blender's float
    // coordinates would turn that into real offsets. Pin it to 1 where the box holds one loop
    // (narrower than the cut spacing); for several loops it spaces them and is kept.
    for (std::vector<Json>* part : {&out.profile, &out.grid}) {
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
    out.scale = ops[i++];
    for (Json& op : out.ridge) op = ops[i++];
    for (Json& op : out.deforms) op = ops[i++];
    for (Json& op : out.details) op = ops[i++];
    if (subdivide) ++i;
    out.rotate = ops[i++];
    out.translate = ops[i++];
    return out;
  }
};

struct Trial {
  Layout layout;
  double loss = kInf;
  bool ok = false;
};

class Controller {
 public:
  Controller(const Target& target, const ZeroShotOptions& options)
      : target_(target), options_(options), start_(Clock::now()) {
    search_options_.seed = options.seed;
    search_options_.num_threads = options.num_threads;
    search_options_.optimizer = options.optimizer;
    search_options_.metric = options.metric;
    search_options_.num_output_samples = 1500;
    search_options_.num_target_samples = 1500;
    search_options_.max_outer_iterations = 8;
    search_options_.max_inner_iterations = 20;
    final_options_ = search_options_;
    final_options_.num_output_samples = 4000;
    final_options_.num_target_samples = 4000;
    final_options_.max_outer_iterations = 15;
    final_options_.max_inner_iterations = 30;
  }

  ZeroShotResult Run() {
    Trial best = FitGlobalAffine();
    if (!best.ok) throw std::runtime_error("the global affine fit failed");
    best = ConsiderSmoothing(best);
    best = ChooseMainForm(best);
    // Stages feed each other (a bend lets a profile help, a profile gives extrusions faces), so
    // they repeat until a whole pass changes nothing.
    for (int pass = 0; pass < 3 && InBudget(); ++pass) {
      const double before = best.loss;
      best = StageSlab(best);
      best = StageProfile(best);
      best = StageDeforms(best);
      best = StageRidge(best);
      best = StageHoles(best);
      best = RepeatDetails(best);
      best = StageGrid(best);
      // Rounding comes after the extrusions, as a modeller would bevel: a bevel first would
      // round the cage toward a protrusion and split its faces below the extrusions' support.
      best = StageBevel(best);
      best = ConsiderSmoothing(best);
      if (!(best.loss < before)) break;
    }
    return Finish(best);
  }

 private:
  // The first decision shapes the rest of a greedy search (a profile accepted for a small gain
  // blocks the extrusion that explains a boss; a small bend blocks a profile), so it is made
  // best-first: every stage runs from the pose (a rounded box is a Bevel of it), and the one
  // with the lowest loss after the price of its ops wins. The passes then add to it in a fixed order.
  Trial ChooseMainForm(const Trial& start) {
    using Stage = Trial (Controller::*)(Trial);
    const std::pair<const char*, Stage> stages[] = {{"slab", &Controller::StageSlab},
                                                    {"profile", &Controller::StageProfile},
                                                    {"deform", &Controller::StageDeforms},
                                                    {"ridge", &Controller::StageRidge},
                                                    {"hole", &Controller::StageHoles},
                                                    {"detail", &Controller::RepeatDetails},
                                                    {"bevel", &Controller::StageBevel}};
    Trial chosen = start;
    double chosen_score = start.loss;
    std::string chosen_stage;
    Vec3d chosen_half_extent = half_extent_;
    const Vec3d start_half_extent = half_extent_;
    for (const auto& [name, stage] : stages) {
      if (!InBudget()) break;
      half_extent_ = start_half_extent;
      const Trial trial = (this->*stage)(start);
      const int added = trial.layout.NumOps() - start.layout.NumOps();
      const double score = trial.ok ? trial.loss / Price(added) : kInf;
      if (score < chosen_score) chosen = trial, chosen_score = score, chosen_stage = name, chosen_half_extent = half_extent_;
    }
    half_extent_ = chosen_half_extent;
    if (!chosen_stage.empty()) Log("main form", start, chosen, true, "the " + chosen_stage + " stage's result");
    return chosen;
  }

  // Proposals stop at this share of the budget; the finishing fits (gate pruning, polishing,
  // simplification: 20-40 s on a 20-op sequence) take the rest.
  static constexpr double kSearchShare = 0.65;
  bool InBudget() const {
    const bool in_budget = Seconds() < kSearchShare * options_.time_budget_seconds;
    budget_ended_search_ = budget_ended_search_ || !in_budget;
    return in_budget;
  }
  double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  // Domain rules of a modeller's sequence, as soft ranges: an extrusion tilts by at most 45
  // degrees (beyond that its side walls fold over the cap: a shear, not an extrusion) and
  // scales its cap by 0.1 to 10 (a fit once shrank a face to a speck with an inset and blew it
  // up 370 times, which multiplies Blender's float32 rounding into the replay); an inset keeps
  // a rim of at least 1% of the cube's smallest half extent (a zero rim is a degenerate ring).
  FitterOptions WithDomainRules(FitterOptions options, const Json& document) const {
    constexpr double kMaxTilt = kPi / 4;
    constexpr int kWidth = 1, kTiltU = 2, kTiltV = 3;  // Extrude's: height, width, tilt_u, tilt_v
    constexpr int kThickness = 0;          // Inset's parameters: thickness, depth
    const Json& ops = document.at("operations");
    for (int k = 0; k < static_cast<int>(ops.size()); ++k) {
      if (ops[k].at("op") == "Extrude") {
        for (int param : {kTiltU, kTiltV}) options.domain_rules.push_back({k, param, -kMaxTilt, kMaxTilt, 1.0});
        options.domain_rules.push_back({k, kWidth, 0.1, 10.0, 1.0});
      }
      if (ops[k].at("op") == "Inset") options.domain_rules.push_back({k, kThickness, 0.01 * half_extent_.minCoeff(), kInf, 1.0});
    }
    return options;
  }

  Trial Fit(const Layout& layout, const FitterOptions& options) {
    Trial trial;
    trial.layout = layout;
    if (layout.NumOps() > options_.max_ops) return trial;
    try {
      const Json document = layout.Document();
      Sequence sequence = ParseSequence(document);
      const FitSummary summary = FitSequence(target_, &sequence, WithDomainRules(options, document));
      ++num_fits_;
      trial.layout = layout.WithParameters(SequenceToJson(sequence));
      // The written sequence must replay: its selectors re-resolve at the fitted parameters.
      Sequence replay = ParseSequence(trial.layout.Document());
      trial.loss = summary.final_loss;
      const std::vector<Mesh> steps = EvaluateSequence(&replay);
      trial.ok = std::isfinite(trial.loss) && !BreaksReplay(document, steps);
    } catch (const std::exception&) {
      trial.ok = false;  // a proposal whose targets vanish or whose fit fails is rejected
    }
    return trial;
  }

  using Proposal = std::function<std::string(Layout*)>;

  // Fits `propose`'s change of `best`; keeps it when the loss falls by more than the price of
  // the ops it adds.
  Trial Consider(const std::string& stage, const Trial& best, const Proposal& propose, double gain_per_op = 0) {
    return ConsiderBest(stage, best, {propose}, gain_per_op);
  }

  // The factor a loss must fall by to pay for `added` ops (below 1; above 1 when ops are
  // removed): `min_relative_gain` per op, or `gain_per_op` when larger.
  double Price(int added, double gain_per_op = 0) const {
    return std::pow(1.0 - std::max(gain_per_op, options_.min_relative_gain), added);
  }

  // Special-purpose structures (a hole, a ridge) can also lower the loss a little where the
  // target has none, by bending the cage toward it; they must explain a quarter of the loss
  // per op they add, and then the general proposals that follow are not blocked by them.
  static constexpr double kStructureGainPerOp = 0.25;

  // Fits each alternative change of `best` and keeps the one whose loss, divided by the price
  // of the ops it adds, is lowest, if that is below the loss of `best`. A proposal that
  // shortens the sequence may cost some loss: the same price per op. The price per op is
  // `min_relative_gain`, or `gain_per_op` when larger.
  Trial ConsiderBest(const std::string& stage, const Trial& best, const std::vector<Proposal>& alternatives,
                     double gain_per_op = 0) {
    Trial chosen = best;
    double chosen_score = best.loss;
    std::string chosen_what;
    for (const Proposal& propose : alternatives) {
      if (!InBudget()) break;
      Layout layout = best.layout;
      const std::string what = propose(&layout);
      if (what.empty()) continue;
      const Trial trial = Fit(layout, search_options_);
      const int added = layout.NumOps() - best.layout.NumOps();
      const double score = trial.ok ? trial.loss / Price(added, gain_per_op) : kInf;
      const bool better = score < chosen_score;
      if (better) {
        chosen = trial, chosen_score = score, chosen_what = what;
      } else {
        Log(stage, best, trial, false, what);
      }
    }
    if (!chosen_what.empty()) Log(stage, best, chosen, true, chosen_what);
    return chosen;
  }

  void Log(const std::string& stage, const Trial& before, const Trial& after, bool accepted, const std::string& what) {
    std::ostringstream line;
    line.precision(3);
    line << "[zero-shot] " << stage << ": " << what << ": loss " << before.loss << " -> "
         << (after.ok ? after.loss : kInf) << (accepted ? " accepted" : " rejected") << " ("
         << (accepted ? after : before).layout.NumOps() << " ops, " << num_fits_ << " fits, " << std::fixed
         << Seconds() << " s)";
    decisions_.push_back(line.str());
    if (options_.progress != nullptr) *options_.progress << line.str() << std::endl;
  }

  // Cube scaled to the target's extent along its principal axes (identity when they are close
  // to the coordinate axes, as for models built axis-aligned), rotated and translated onto it.
  Trial FitGlobalAffine() {
    const Positions<double>& points = target_.points();
    Vec3d mean = Vec3d::Zero();
    for (const Vec3d& p : points) mean += p;
    mean /= static_cast<double>(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3d& p : points) covariance += (p - mean) * (p - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    Eigen::Matrix3d principal = PrincipalFrame(eigen.eigenvalues(), eigen.eigenvectors(), mean);
    // Models are often built axis-aligned: the coordinate axes are tried too, and kept unless
    // clearly worse.
    Trial aligned = FitPose(Eigen::Matrix3d::Identity());
    const Vec3d aligned_half = half_extent_;
    Trial rotated = FitPose(principal);
    if (aligned.ok && !(rotated.loss < 0.7 * aligned.loss)) {
      half_extent_ = aligned_half;
      world_from_local_ = Eigen::Matrix3d::Identity();
      Log("affine", aligned, aligned, true, "Scale, Rotate, Translate (coordinate axes)");
      return aligned;
    }
    Log("affine", rotated, rotated, true, "Scale, Rotate, Translate (principal axes)");
    return rotated;
  }

  // A frame of principal axes (columns, right-handed). Axes of (near) equal variance are
  // arbitrary (a plus sign, a square plate, a cylinder): when two are, the pair is turned about
  // the third axis to the smallest bounding rectangle (a plus sign's arms, a plate's sides);
  // when all three are, the coordinate axes are used.
  Eigen::Matrix3d PrincipalFrame(const Vec3d& variances, const Eigen::Matrix3d& axes, const Vec3d& mean) const {
    auto near_equal = [&](int a, int b) { return std::abs(variances[a] - variances[b]) < 0.15 * std::max(variances[a], variances[b]); };
    Eigen::Matrix3d frame = axes;
    if (near_equal(0, 1) && near_equal(1, 2)) return Eigen::Matrix3d::Identity();
    if (near_equal(0, 1) || near_equal(1, 2)) {
      const int distinct = near_equal(0, 1) ? 2 : 0;
      const Vec3d e1 = axes.col((distinct + 1) % 3), e2 = axes.col((distinct + 2) % 3);
      const Positions<double>& points = target_.points();
      const size_t stride = std::max<size_t>(1, points.size() / 5000);
      double best_area = kInf;
      for (int step = 0; step < 180; ++step) {
        const double angle = DegToRad(0.5 * step);
        const Vec3d a = std::cos(angle) * e1 + std::sin(angle) * e2, b = -std::sin(angle) * e1 + std::cos(angle) * e2;
        double a_lo = kInf, a_hi = -kInf, b_lo = kInf, b_hi = -kInf;
        for (size_t i = 0; i < points.size(); i += stride) {
          const double x = a.dot(points[i] - mean), y = b.dot(points[i] - mean);
          a_lo = std::min(a_lo, x), a_hi = std::max(a_hi, x), b_lo = std::min(b_lo, y), b_hi = std::max(b_hi, y);
        }
        const double area = (a_hi - a_lo) * (b_hi - b_lo);
        if (area < best_area) best_area = area, frame.col((distinct + 1) % 3) = a, frame.col((distinct + 2) % 3) = b;
      }
    }
    if (frame.determinant() < 0) frame.col(2) *= -1;
    return frame;
  }

  // The cube fitted onto the target's box in the frame `world_from_local`.
  Trial FitPose(const Eigen::Matrix3d& world_from_local) { return Fit(PoseLayout(world_from_local), search_options_); }

  // The cube placed on the target's box in the frame `world_from_local`; along `slab_axis`
  // (when >= 0) on [slab_lo, slab_hi] instead.
  Layout PoseLayout(const Eigen::Matrix3d& world_from_local, int slab_axis = -1, double slab_lo = 0, double slab_hi = 0) {
    const Positions<double>& points = target_.points();
    Vec3d lo = Vec3d::Constant(kInf), hi = Vec3d::Constant(-kInf);
    for (const Vec3d& p : points) {
      const Vec3d q = world_from_local.transpose() * p;
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
    if (slab_axis >= 0) lo[slab_axis] = slab_lo, hi[slab_axis] = slab_hi;
    world_from_local_ = world_from_local;
    const double extent = (hi - lo).maxCoeff();
    const Vec3d half = ((hi - lo) / 2).cwiseMax(Vec3d::Constant(1e-3 * extent));
    // R = Rz Ry Rx: Eigen's eulerAngles(2, 1, 0) returns (z, y, x).
    const Vec3d zyx = world_from_local.eulerAngles(2, 1, 0);
    Layout layout;
    layout.scale = MakeOp("GlobalAffineScale", {{"scale", ToJson(half)}});
    layout.rotate = MakeOp("GlobalAffineRotate",
                           {{"rotation_deg", ToJson(Vec3d(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0])))}});
    layout.translate = MakeOp("GlobalAffineTranslate", {{"offset", ToJson(Vec3d(world_from_local * ((hi + lo) / 2)))}});
    half_extent_ = half;
    return layout;
  }

  Trial ConsiderSmoothing(const Trial& best) {
    return Consider("smooth", best, [&](Layout* l) -> std::string {
      if (l->subdivide) return "";
      l->subdivide = true;
      return "+Subdivision(2)";
    });
  }

  int LongAxis() const {
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
      if (half_extent_[a] > half_extent_[axis]) axis = a;
    }
    return axis;
  }

  // LoopCut along `axis` on the cube with one EdgeLoopAffineScale per group of neighbouring new
  // loops (`groups`: loop indices, each group contiguous; empty = one per loop). `expect`: a
  // loop's vertex count, < 0 when earlier cuts make it vary.
  static std::vector<Json> LoopOps(int axis, int cuts, int expect, std::vector<std::vector<int>> groups = {}) {
    std::vector<Json> ops = {MakeOp("LoopCut", {{"axis", kAxisNames[axis]}, {"cuts", cuts}, {"near", {0, 0, 0}}})};
    if (groups.empty()) {
      for (int i = 0; i < cuts; ++i) groups.push_back({i});
    }
    const double spacing = 2.0 / (cuts + 1);
    for (const std::vector<int>& group : groups) {
      Json lo = {nullptr, nullptr, nullptr}, hi = {nullptr, nullptr, nullptr};
      lo[axis] = -1.0 + spacing * (group.front() + 1) - 0.3 * spacing;
      hi[axis] = -1.0 + spacing * (group.back() + 1) + 0.3 * spacing;
      Json verts = {{"box", {lo, hi}}};
      if (expect > 0) verts["expect"] = expect * static_cast<int>(group.size());
      ops.push_back(MakeOp("EdgeLoopAffineScale", {{"verts", verts}, {"scale", {1.0, 1.0, 1.0}}}));
    }
    return ops;
  }

  // Profiles along the long axis, simplest first: a waist or bulge (two loops scaled together),
  // a pinch between two end sections (the inner two of four), the end loops apart, then one scale
  // per loop. A richer profile replaces a simpler one only when it pays for its extra ops.
  Trial StageProfile(Trial best) {
    const int axis = LongAxis();
    struct Profile {
      int cuts;
      std::vector<std::vector<int>> groups;  // empty: one scale per loop
      std::string name;
    };
    const std::vector<Profile> profiles = {{2, {{0, 1}}, "x2, the two loops scaled together"},
                                           {4, {{1, 2}}, "x4, the inner two loops scaled together"},
                                           {2, {}, "x2, each loop scaled"},
                                           {4, {{0}, {1, 2}, {3}}, "x4, ends and middle scaled"},
                                           {4, {}, "x4, each loop scaled"},
                                           {8, {}, "x8, each loop scaled"}};
    for (const Profile& profile : profiles) {
      const std::string name = "LoopCut " + std::string(kAxisNames[axis]) + " " + profile.name;
      // Tried again in every pass: a bend or a hole accepted since can make a profile pay.
      if (best.layout.profile_name == name) continue;
      // A round form (a barrel, a vase) is a profile on a subdivided cage: neither alone
      // lowers the loss much, so the profile is also tried with Subdivision.
      auto with_profile = [&](bool subdivide) -> Proposal {
        return [&, subdivide](Layout* l) -> std::string {
          if (subdivide && l->subdivide) return "";
          l->profile = LoopOps(axis, profile.cuts, 4, profile.groups);
          l->profile_name = name;
          l->subdivide = l->subdivide || subdivide;
          return name + (subdivide ? " + Subdivision(2)" : "");
        };
      };
      best = ConsiderBest("profile", best, {with_profile(false), with_profile(true)});
    }
    return best;
  }

  Trial StageDeforms(Trial best) {
    const int axis = LongAxis();
    struct Deform {
      std::string op;
      int axis;
      Json params;
    };
    // Starts on both sides of the identity, and a large twist (LM does not cross the twist
    // of a square section by a quarter turn from a small start).
    std::vector<Deform> deforms = {{"SimpleDeformTwist", axis, {{"angle_deg", 30.0}}},
                                   {"SimpleDeformTwist", axis, {{"angle_deg", -30.0}}},
                                   {"SimpleDeformTwist", axis, {{"angle_deg", 150.0}}},
                                   {"SimpleDeformTwist", axis, {{"angle_deg", -150.0}}},
                                   {"SimpleDeformTaper", axis, {{"factor", 0.2}}},
                                   {"SimpleDeformTaper", axis, {{"factor", -0.2}}}};
    for (int a = 0; a < 3; ++a) {
      if (a == axis) continue;
      deforms.push_back({"SimpleDeformBend", a, {{"angle_deg", 30.0}}});
      deforms.push_back({"SimpleDeformBend", a, {{"angle_deg", -30.0}}});
    }
    for (const Deform& deform : deforms) {
      best = Consider("deform", best, [&](Layout* l) -> std::string {
        for (const Json& op : l->deforms) {
          if (op["op"] == deform.op && op["params"]["axis"] == kAxisNames[deform.axis]) return "";
        }
        Json params = deform.params;
        params["axis"] = kAxisNames[deform.axis];
        l->deforms.push_back(MakeOp(deform.op, params));
        std::string what = "+" + deform.op + " " + kAxisNames[deform.axis];
        // Deformations need rings along the long axis to bend smoothly.
        if (l->profile.empty()) {
          l->profile = {MakeOp("LoopCut", {{"axis", kAxisNames[axis]}, {"cuts", 7}, {"near", {0, 0, 0}}})};
          l->profile_name = "LoopCut x7";
          what += " (with LoopCut " + std::string(kAxisNames[axis]) + " x7)";
        }
        return what;
      });
    }
    return best;
  }

  // A ridge or a peak (a gable roof): a loop cut across one axis, and the cut's vertices on one
  // side of another axis raised along it. Every axis pair and side is fitted; the best one is
  // kept if it pays for its two ops.
  Trial StageRidge(Trial best) {
    if (!best.layout.ridge.empty() || !InBudget()) return best;
    const Json& scale = best.layout.scale["params"]["scale"];
    Trial best_ridge;
    std::string best_what;
    for (int cut = 0; cut < 3; ++cut) {
      for (int up = 0; up < 3; ++up) {
        for (int sign : {1, -1}) {
          if (up == cut || !InBudget()) continue;
          const double cut_half = std::abs(scale[cut].get<double>()), up_half = std::abs(scale[up].get<double>());
          Json lo = {nullptr, nullptr, nullptr}, hi = {nullptr, nullptr, nullptr};
          lo[cut] = -0.25 * cut_half, hi[cut] = 0.25 * cut_half;
          (sign > 0 ? lo : hi)[up] = sign * 0.5 * up_half;
          Vec3d offset = Vec3d::Zero();
          offset[up] = sign * 0.5 * up_half;
          Layout layout = best.layout;
          layout.ridge = {MakeOp("LoopCut", {{"axis", kAxisNames[cut]}, {"cuts", 1}, {"near", {0, 0, 0}}}),
                          MakeOp("VertexDisplace", {{"groups", Json::array({Json{{"verts", {{"box", {lo, hi}}}}, {"offset", ToJson(offset)}}})}})};
          const Trial trial = Fit(layout, search_options_);
          if (trial.ok && (!best_ridge.ok || trial.loss < best_ridge.loss)) {
            best_ridge = trial;
            best_what = std::string("LoopCut ") + kAxisNames[cut] + " x1, its vertices raised along " + (sign > 0 ? "+" : "-") + kAxisNames[up];
          }
        }
      }
    }
    if (!best_ridge.ok) return best;
    const bool accept = best_ridge.loss < best.loss * Price(2, kStructureGainPerOp);
    Log("ridge", best, best_ridge, accept, best_what);
    return accept ? best_ridge : best;
  }

  // Holes through the shape (a ring, a handle's eye): a Boolean difference with a prism or a box
  // through the centre along each axis; the fit sizes and places it.
  Trial StageHoles(Trial best) {
    // The prism also turned an eighth of a turn about its axis, so its flat sides face the
    // cube's (sides parallel to the sides around them subdivide evenly).
    for (const auto& [primitive, spin_deg] : {std::pair<const char*, double>{"prism8", 0.0}, {"prism8", 22.5}, {"cube", 0.0}}) {
      for (int axis = 0; axis < 3 && InBudget(); ++axis) {
        best = Consider("hole", best, [&](Layout* l) -> std::string {
          for (const Json& op : l->details) {
            if (op["op"] == "Boolean") return "";
          }
          Vec3d size = half_extent_;  // half the extent across the axis, through it entirely
          size[axis] = 6 * half_extent_[axis];
          // The prism's axis is +Z: spin it about that axis, then turn it onto `axis`.
          Eigen::Matrix3d onto_axis = Eigen::Matrix3d::Identity();
          if (axis == 0) onto_axis = Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitY()).toRotationMatrix();
          if (axis == 1) onto_axis = Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitX()).toRotationMatrix();
          const Eigen::Matrix3d world_from_primitive = onto_axis * Eigen::AngleAxisd(DegToRad(spin_deg), Vec3d::UnitZ()).toRotationMatrix();
          const Vec3d zyx = world_from_primitive.eulerAngles(2, 1, 0);  // R = Rz Ry Rx
          const Vec3d rotation_deg(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0]));
          Vec3d size_in_primitive = size;
          if (axis == 0) size_in_primitive = Vec3d(size.z(), size.y(), size.x());
          if (axis == 1) size_in_primitive = Vec3d(size.x(), size.z(), size.y());
          l->details.push_back(MakeOp("Boolean", {{"operation", "DIFFERENCE"},
                                                  {"primitive", primitive},
                                                  {"size", ToJson(size_in_primitive)},
                                                  {"rotation_deg", ToJson(rotation_deg)},
                                                  {"location", {0.0, 0.0, 0.0}}}));
          return std::string("+Boolean difference ") + primitive + (spin_deg != 0 ? " (turned)" : "") + " along " + kAxisNames[axis];
        }, kStructureGainPerOp);
      }
    }
    return best;
  }

  // Rounded edges: Bevel on the edges sharper than 30 degrees, first with 5 segments, then the
  // segment count searched (same op count, so the lowest loss wins).
  Trial StageBevel(Trial best) {
    for (const Json& op : best.layout.details) {
      if (op["op"] == "Bevel") return best;
    }
    const double width = 0.05 * half_extent_.minCoeff();
    const Json bevel = MakeOp("Bevel", {{"width", width}, {"segments", 5}, {"limit_method", "ANGLE"}, {"angle_limit_deg", 30.0}});
    best = Consider("bevel", best, [&](Layout* l) -> std::string {
      l->details.push_back(bevel);
      return "+Bevel (5 segments)";
    });
    // Extrusions can imitate rounded edges (a slab's rim grown outward): a bevel alone may
    // explain them with fewer ops.
    if (!best.layout.details.empty() && best.layout.details.back()["op"] != "Bevel") {
      best = Consider("bevel", best, [&](Layout* l) -> std::string {
        l->details = {MakeOp("Bevel", {{"width", 4 * width}, {"segments", 5}, {"limit_method", "ANGLE"}, {"angle_limit_deg", 30.0}})};
        l->grid.clear();  // the grid was there for the extrusions
        return "Bevel (5 segments) instead of the extrusions";
      });
    }
    if (best.layout.details.empty() || best.layout.details.back()["op"] != "Bevel") return best;
    for (int segments : {1, 2, 3, 4, 6, 9}) {
      if (!InBudget()) break;
      Layout layout = best.layout;
      layout.details.back()["params"]["segments"] = segments;
      const Trial trial = Fit(layout, search_options_);
      const bool accept = trial.ok && trial.loss < best.loss;
      Log("bevel", best, trial, accept, "segments " + std::to_string(segments));
      if (accept) best = trial;
    }
    return best;
  }

  Trial RepeatDetails(Trial best) {
    for (int round = 0; round < 6 && InBudget(); ++round) {
      const double before = best.loss;
      best = StageDetails(best);
      if (!(best.loss < before)) break;
    }
    return best;
  }

  // Loop cuts across two axes give faces where extrusions can start (legs at a table's
  // corners, arms in the middle of a side). Cuts alone do not change the surface, so each grid
  // is judged with the extrusions it enables (one step of lookahead).
  Trial StageGrid(Trial best) {
    if (!best.layout.grid.empty()) return best;
    for (int a = 0; a < 3 && InBudget(); ++a) {
      for (int b = a + 1; b < 3 && InBudget(); ++b) {
        Layout layout = best.layout;
        // A scale of both loops of an axis spaces them, so the new faces move to where the
        // extrusions belong (a leg at a corner).
        layout.grid = LoopOps(a, 2, layout.profile.empty() ? 4 : -1, {{0, 1}});
        const std::vector<Json> second = LoopOps(b, 2, -1, {{0, 1}});
        layout.grid.insert(layout.grid.end(), second.begin(), second.end());
        Trial trial = Fit(layout, search_options_);
        if (!trial.ok) continue;
        const std::string what = std::string("LoopCut grid ") + kAxisNames[a] + kAxisNames[b];
        Log("grid", best, trial, false, what + " (before its extrusions)");
        const size_t details_before = trial.layout.details.size();
        trial = RepeatDetails(trial);
        const int added = trial.layout.NumOps() - best.layout.NumOps();
        // A grid is there for its extrusions: without any, its loop scales would only be a
        // second profile.
        const bool accept = trial.layout.details.size() > details_before &&
                            trial.loss < best.loss * Price(added);
        Log("grid", best, trial, accept, what + " with its extrusions");
        if (accept) best = trial;
      }
    }
    return best;
  }

  // The body of a table or a stool: along some axis, the largest layer of the target's surface
  // facing + and the largest facing - bound a slab clearly thinner than the bounding box, and
  // the rest grows out of it. Returns the axis (-1 when none) and the slab's bounds, in the
  // frame of the global affine fit.
  std::tuple<int, double, double> FindSlab() const {
    const Positions<double>& points = target_.points();
    const Positions<double>& normals = target_.normals();
    constexpr int kBins = 100;
    int best_axis = -1;
    double best_weight = 0, best_lo = 0, best_hi = 0;
    for (int axis = 0; axis < 3; ++axis) {
      double lo = kInf, hi = -kInf;
      for (const Vec3d& p : points) {
        const double x = world_from_local_.col(axis).dot(p);
        lo = std::min(lo, x), hi = std::max(hi, x);
      }
      if (!(hi - lo > 0)) continue;
      std::vector<double> plus(kBins, 0), minus(kBins, 0);
      for (size_t i = 0; i < points.size(); ++i) {
        const int bin = std::clamp(static_cast<int>((world_from_local_.col(axis).dot(points[i]) - lo) / (hi - lo) * kBins), 0, kBins - 1);
        const double facing = world_from_local_.col(axis).dot(normals[i]);
        if (facing > 0.9) plus[bin] += 1;
        if (facing < -0.9) minus[bin] += 1;
      }
      // Layers of three bins, so a layer on a bin boundary counts whole.
      auto densest = [&](const std::vector<double>& count) {
        int best = 0;
        double weight = 0;
        for (int b = 0; b < kBins; ++b) {
          const double w = count[b] + (b > 0 ? count[b - 1] : 0) + (b + 1 < kBins ? count[b + 1] : 0);
          if (w > weight) weight = w, best = b;
        }
        return std::make_pair(best, weight);
      };
      const auto [top, top_weight] = densest(plus);
      const auto [bottom, bottom_weight] = densest(minus);
      const double n = static_cast<double>(points.size());
      // A slab: thinner than 60% of the box, both layers holding 5% of the samples.
      if (bottom >= top || top - bottom > 0.6 * kBins || std::min(top_weight, bottom_weight) < 0.05 * n) continue;
      if (top_weight + bottom_weight > best_weight) {
        best_axis = axis, best_weight = top_weight + bottom_weight;
        best_lo = lo + (bottom + 0.5) / kBins * (hi - lo);
        best_hi = lo + (top + 0.5) / kBins * (hi - lo);
      }
    }
    return {best_axis, best_lo, best_hi};
  }

  // A slab as the body (see FindSlab) with a loop-cut grid across it and the extrusions that
  // grow the rest (a table's legs), judged against the best sequence as a whole.
  Trial StageSlab(Trial best) {
    if (slab_tried_ || !InBudget()) return best;
    slab_tried_ = true;
    const auto [axis, lo, hi] = FindSlab();
    if (axis < 0) return best;
    const Vec3d half_extent = half_extent_;
    // The slab is not fitted alone: the rest of the target would pull it back to the bounding
    // box. Its extrusions are proposed from the placed slab and fitted with it; with a loop-cut
    // grid across it (legs at the corners) and without (a boss on the whole face).
    Trial chosen = best;
    for (bool grid : {false, true}) {
      if (!InBudget()) break;
      Trial trial;
      trial.layout = PoseLayout(world_from_local_, axis, lo, hi);
      if (grid) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        trial.layout.grid = LoopOps(std::min(a, b), 2, 4, {{0, 1}});
        const std::vector<Json> second = LoopOps(std::max(a, b), 2, -1, {{0, 1}});
        trial.layout.grid.insert(trial.layout.grid.end(), second.begin(), second.end());
      }
      trial.ok = true;  // with an unknown (infinite) loss, so its first extrusions are taken
      trial = RepeatDetails(trial);
      trial.ok = std::isfinite(trial.loss);
      const int added = trial.layout.NumOps() - chosen.layout.NumOps();
      const bool accept = trial.ok && trial.loss < chosen.loss * Price(added);
      Log("slab", chosen, trial, accept,
          std::string("slab across ") + kAxisNames[axis] + (grid ? " with a LoopCut grid" : "") + " and its extrusions");
      if (accept) chosen = trial;
    }
    if (chosen.layout.Document() != best.layout.Document()) return chosen;
    half_extent_ = half_extent;
    return best;
  }

  // Extrude proposals from the residuals: target samples, brought into the cube's frame, are
  // assigned to the nearest cage face; faces with many samples far outside (protrusion) or
  // inside (cavity) along their normal become candidates.
  Trial StageDetails(Trial best) {
    Sequence sequence = ParseSequence(best.layout.Document());
    const std::vector<Mesh> steps = EvaluateSequence(&sequence);
    const Mesh& cage = steps[best.layout.CageStep()];
    const Json& rotation = best.layout.rotate["params"]["rotation_deg"];
    const Json& offset = best.layout.translate["params"]["offset"];
    const Eigen::Matrix3d world_from_local =
        EulerXYZToMatrix(DegToRad(rotation[0]), DegToRad(rotation[1]), DegToRad(rotation[2]));
    const Vec3d translation(offset[0], offset[1], offset[2]);
    const int num_faces = cage.NumFaces();
    std::vector<Vec3d> centroids(num_faces), normals(num_faces);
    for (int f = 0; f < num_faces; ++f) {
      centroids[f] = FaceCentroid(cage.vertices, cage.faces[f]);
      normals[f] = SafeNormalized(FaceAreaNormal(cage.vertices, cage.faces[f]));
    }
    const double diagonal = 2.0 * half_extent_.norm();
    const double threshold = 0.04 * diagonal;
    std::vector<std::vector<double>> outside(num_faces), inside(num_faces);
    // Mean squared distance of the outside samples from the face's normal line: a narrow
    // protrusion starts from a narrowed cap (the Extrude's width).
    std::vector<double> outside_spread(num_faces, 0.0);
    const Positions<double>& points = target_.points();
    const size_t stride = std::max<size_t>(1, points.size() / 4000);
    for (size_t i = 0; i < points.size(); i += stride) {
      const Vec3d q = world_from_local.transpose() * (points[i] - translation);
      int nearest = 0;
      double nearest_distance = kInf;
      for (int f = 0; f < num_faces; ++f) {
        const double d = (q - centroids[f]).squaredNorm();
        if (d < nearest_distance) nearest_distance = d, nearest = f;
      }
      const double along = (q - centroids[nearest]).dot(normals[nearest]);
      if (along > threshold) {
        outside[nearest].push_back(along);
        outside_spread[nearest] += ((q - centroids[nearest]) - along * normals[nearest]).squaredNorm();
      }
      if (along < -threshold) inside[nearest].push_back(-along);
    }
    const size_t min_support = std::max<size_t>(5, points.size() / stride / 100);
    struct Candidate {
      int face;
      double height;  // signed
      size_t support;
      double width = 1;
    };
    std::vector<Candidate> candidates;
    for (int f = 0; f < num_faces; ++f) {
      for (int sign : {1, -1}) {
        std::vector<double>& d = sign > 0 ? outside[f] : inside[f];
        if (d.size() < min_support) continue;
        std::nth_element(d.begin(), d.begin() + d.size() * 3 / 4, d.end());
        Candidate candidate{f, sign * d[d.size() * 3 / 4], d.size()};
        if (sign > 0) {
          // Uniform samples over a square of side L lie sqrt(1/6) L from its centre (RMS).
          const double face_spread = std::sqrt(FaceAreaNormal(cage.vertices, cage.faces[f]).norm() / 6.0);
          const double spread = std::sqrt(outside_spread[f] / static_cast<double>(d.size()));
          candidate.width = std::clamp(spread / std::max(face_spread, 1e-12), 0.1, 1.0);
        }
        candidates.push_back(candidate);
      }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.support * std::abs(a.height) > b.support * std::abs(b.height);
    });
    // Faces wanting the same growth (a table's four legs, a cross's arms) are proposed
    // together, as one Extrude on all of them, before the single faces.
    std::vector<std::vector<Candidate>> proposals;
    std::vector<bool> grouped(candidates.size(), false);
    for (size_t i = 0; i < candidates.size(); ++i) {
      std::vector<Candidate> group = {candidates[i]};
      for (size_t j = i + 1; j < candidates.size(); ++j) {
        const Candidate& a = candidates[i];
        const Candidate& b = candidates[j];
        if (grouped[j] || (a.height > 0) != (b.height > 0)) continue;
        const bool similar_height = std::abs(a.height - b.height) < 0.3 * std::abs(a.height);
        const bool same_direction = normals[a.face].dot(normals[b.face]) > 0.9;
        // Symmetric growth on opposite or perpendicular sides counts as a pattern too.
        const bool same_size = std::abs(static_cast<double>(b.support) - static_cast<double>(a.support)) < 0.5 * a.support;
        if (similar_height && (same_direction || same_size)) group.push_back(b), grouped[j] = true;
      }
      if (group.size() > 1) proposals.push_back(group);
    }
    for (size_t i = 0; i < candidates.size() && i < 6; ++i) proposals.push_back({candidates[i]});
    for (const std::vector<Candidate>& group : proposals) {
      Json centers = Json::array();
      double height = 0, width = 0, side = 0;
      for (const Candidate& c : group) {
        centers.push_back(ToJson(centroids[c.face]));
        height += c.height / static_cast<double>(group.size());
        width += c.width / static_cast<double>(group.size());
        side += std::sqrt(FaceAreaNormal(cage.vertices, cage.faces[c.face]).norm()) / static_cast<double>(group.size());
      }
      Json faces = {{"centers", centers}, {"expect", group.size()}};
      // A shared normal keeps the selector on the same faces when an edit moves their centres.
      bool shared_normal = true;
      for (const Candidate& c : group) shared_normal = shared_normal && normals[c.face].dot(normals[group[0].face]) > 0.99;
      if (shared_normal) faces["normal"] = ToJson(normals[group[0].face]), faces["min_dot"] = 0.9;
      const std::string count = group.size() > 1 ? " x" + std::to_string(group.size()) : "";
      // A narrower protrusion or a hole with a rim: the cap narrowed (a tapered wall), or the
      // faces inset first and the inner faces extruded (a straight wall, as a modeller does).
      const double inset_width = height > 0 ? width : 0.7;
      std::vector<Proposal> alternatives;
      if (height > 0) {
        alternatives.push_back([&](Layout* l) -> std::string {
          l->details.push_back(MakeOp("Extrude", {{"faces", faces}, {"height", height}, {"width", width}, {"mode", "individual"}}));
          return "+Extrude out" + count + " " + std::to_string(height) + " width " + std::to_string(width);
        });
      }
      // Only on faces sharing one plane's normal: an inset region that folds between faces at a
      // boundary corner can differ from Blender's (ops/inset.h).
      bool coplanar_normals = true;
      for (const Candidate& c : group) coplanar_normals = coplanar_normals && normals[c.face].dot(normals[group[0].face]) > 1 - 1e-9;
      if (inset_width < 0.8 && coplanar_normals) {
        alternatives.push_back([&](Layout* l) -> std::string {
          const double thickness = 0.5 * (1 - inset_width) * side;
          l->details.push_back(MakeOp("Inset", {{"faces", faces}, {"thickness", thickness}}));
          l->details.push_back(MakeOp("Extrude", {{"faces", faces}, {"height", height}, {"mode", "individual"}}));
          return "+Inset " + std::to_string(thickness) + ", Extrude " + (height > 0 ? "out" : "in") + count + " " +
                 std::to_string(height);
        });
      }
      best = ConsiderBest("detail", best, alternatives);
    }
    return best;
  }

  // Drops ops the result does not need: each op in turn (last first) is removed when the
  // sequence without it still replays and its Chamfer distance to the target grows by under 2%.
  Json Simplify(Json document) {
    MetricsOptions metrics_options;
    metrics_options.num_samples = 3000;
    metrics_options.seed = options_.seed;
    auto chamfer = [&](const Json& candidate) {
      try {
        Sequence sequence = ParseSequence(candidate);
        return ComputeShapeMetrics(EvaluateSequence(&sequence).back(), target_.shape(), metrics_options).chamfer.Sum();
      } catch (const std::exception&) {
        return kInf;
      }
    };
    double current = chamfer(document);
    for (int k = static_cast<int>(document["operations"].size()) - 1; k >= 0; --k) {
      if (document["operations"].size() == 1) break;
      Json candidate = document;
      const std::string name = candidate["operations"][k]["op"];
      candidate["operations"].erase(static_cast<size_t>(k));
      const double without = chamfer(candidate);
      if (without <= current * 1.02 + 1e-7) {
        std::ostringstream line;
        line << "[zero-shot] simplify: removed op " << k << " (" << name << "): Chamfer " << current << " -> " << without;
        decisions_.push_back(line.str());
        if (options_.progress != nullptr) *options_.progress << line.str() << std::endl;
        document = candidate;
        current = without;
      }
    }
    return document;
  }

  // The document with the scale moved first (as modellers order it) when it builds the same
  // mesh: equal counts and every vertex on one of the original's. (A loop cut's seed edge can
  // be another edge of the same ring after the scale, which only reorders the new vertices.)
  Json ScaleFirstIfSame(const Json& document) {
    const Json reordered = ScaleFirst(document);
    if (reordered == document) return document;
    try {
      Sequence original_sequence = ParseSequence(document), reordered_sequence = ParseSequence(reordered);
      const Mesh original = EvaluateSequence(&original_sequence).back();
      const Mesh moved = EvaluateSequence(&reordered_sequence).back();
      if (moved.NumVertices() != original.NumVertices() || moved.NumFaces() != original.NumFaces()) return document;
      const double tolerance = 1e-9 * (2.0 * half_extent_.norm() + 1.0);
      for (const Vec3d& p : moved.vertices) {
        bool found = false;
        for (const Vec3d& q : original.vertices) {
          if ((p - q).squaredNorm() <= tolerance * tolerance) {
            found = true;
            break;
          }
        }
        if (!found) return document;
      }
      return reordered;
    } catch (const std::exception&) {
      return document;
    }
  }

  ZeroShotResult Finish(const Trial& best) {
    // Gates: ops that do not earn their place are pruned, then a polishing fit.
    Sequence sequence = ParseSequence(best.layout.Document());
    FitterOptions options = final_options_;
    options.fit_gates = true;
    double loss = best.loss;
    Json document = best.layout.Document();
    try {
      const FitSummary summary = FitSequence(target_, &sequence, WithDomainRules(options, document));
      ++num_fits_;
      Json fitted = SequenceToJson(sequence);
      Sequence replay = ParseSequence(fitted);
      const bool breaks_replay = BreaksReplay(fitted, EvaluateSequence(&replay));
      // Pruning must not undo what the search paid for.
      if (!breaks_replay && summary.final_loss <= best.loss * (1 + options_.min_relative_gain)) {
        document = fitted;
        loss = summary.final_loss;
      }
      std::ostringstream line;
      line << "[zero-shot] prune: " << summary.pruned_ops.size() << " op(s) below the gate threshold: loss "
           << best.loss << " -> " << summary.final_loss << (document == fitted ? " accepted" : " rejected");
      decisions_.push_back(line.str());
      if (options_.progress != nullptr) *options_.progress << line.str() << std::endl;
    } catch (const std::exception& e) {
      decisions_.push_back(std::string("[zero-shot] final gate fit failed, kept the searched sequence: ") + e.what());
    }
    if (document == best.layout.Document()) {  // polish the searched sequence with more samples
      const Trial polished = Fit(best.layout, final_options_);
      if (polished.ok) document = polished.layout.Document(), loss = polished.loss;
    }
    document = Simplify(document);
    document = ScaleFirstIfSame(document);
    ZeroShotResult result;
    result.sequence = document;
    result.loss = loss;
    result.num_fits = num_fits_;
    result.seconds = Seconds();
    result.decisions = decisions_;
    result.search_complete = !budget_ended_search_;
    if (budget_ended_search_) {
      result.decisions.push_back("[zero-shot] the time budget ended the search before every proposal was tried");
    }
    if (options_.progress != nullptr) {
      *options_.progress << "[zero-shot] final: " << document["operations"].size() << " ops, loss " << loss << ", "
                         << num_fits_ << " fits, " << result.seconds << " s" << std::endl;
    }
    return result;
  }

  const Target& target_;
  ZeroShotOptions options_;
  FitterOptions search_options_;
  FitterOptions final_options_;
  Clock::time_point start_;
  Vec3d half_extent_ = Vec3d::Ones();
  Eigen::Matrix3d world_from_local_ = Eigen::Matrix3d::Identity();  // of the global affine fit
  bool slab_tried_ = false;
  mutable bool budget_ended_search_ = false;  // a proposal was skipped for lack of time
  int num_fits_ = 0;
  std::vector<std::string> decisions_;
};

}  // namespace

std::string ZeroShotOptions::Check() const {
  if (!(time_budget_seconds > 0)) return "time budget must be positive";
  if (max_ops < 3) return "max ops must be at least 3";
  if (!(min_relative_gain >= 0 && min_relative_gain < 1)) return "min relative gain must be in [0, 1)";
  if (num_threads < 1) return "threads must be at least 1";
  return "";
}

ZeroShotResult RecoverSequence(const Target& target, const ZeroShotOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument(problem);
  return Controller(target, options).Run();
}

}  // namespace opgraph
