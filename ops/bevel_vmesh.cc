#include "ops/bevel_vmesh.h"

#include <algorithm>

namespace opgraph {
namespace bevel {

ProfileSpacing::ProfileSpacing(int segments) : seg(segments) {
  seg_2 = 4;
  while (seg_2 < seg) seg_2 *= 2;
  // Circle (r = 2): chords even in angle.
  auto fill = [](int n, std::vector<double>* x, std::vector<double>* y) {
    x->resize(n + 1);
    y->resize(n + 1);
    for (int i = 0; i <= n; ++i) {
      (*x)[i] = std::sin(i * (kPi / 2) / n);
      (*y)[i] = std::cos(i * (kPi / 2) / n);
    }
  };
  fill(seg, &x, &y);
  fill(seg_2, &x2, &y2);
  // Blender's fitted "fullness" of the circle profile per segment count (1..11).
  static const double kCircleFullness[11] = {0.0, 0.559, 0.642, 0.551, 0.646, 0.624,
                                             0.646, 0.619, 0.647, 0.639, 0.647};
  fullness = static_cast<double>(static_cast<float>(kCircleFullness[std::min(seg, 11) - 1]));
}

double SabinGamma(int n) {
  if (n < 3) return 0.0;
  if (n == 3) return static_cast<double>(0.065247584f);
  if (n == 4) return 0.25;
  if (n == 5) return static_cast<double>(0.401983447f);
  if (n == 6) return static_cast<double>(0.523423277f);
  const double k = std::cos(kPi / n), k2 = k * k, k4 = k2 * k2, k6 = k4 * k2;
  const double y = std::pow(std::sqrt(3.0) * std::sqrt(64.0 * k6 - 144.0 * k4 + 135.0 * k2 - 27.0) + 9.0 * k, 1.0 / 3.0);
  const double x = 0.480749856769136 * y - (0.231120424783545 * (12.0 * k2 - 9.0)) / y;
  return (k * x + 2.0 * k2 - 1.0) / (x * x * (k * x + 1.0));
}

VGrid<double> CubeCornerOctant(const ProfileSpacing& spacing) {
  const int nseg = spacing.seg;
  std::vector<Profile<double>> profiles(3);
  VGrid<double> vm0(3, 2);
  for (int i = 0; i < 3; ++i) {
    Profile<double>& pro = profiles[i];
    pro.start = Vec3d::Unit(i);
    pro.end = Vec3d::Unit((i + 1) % 3);
    pro.middle = pro.start + pro.end;
    pro.line = false;
    pro.plane_co = pro.start;
    pro.plane_no = pro.start.cross(pro.end);
    pro.proj_dir = pro.plane_no;
    pro.Calculate(spacing);
    vm0.at(i, 0, 0) = pro.start;
    vm0.at(i, 0, 1) = pro.Point(spacing, 1, 2);
  }
  vm0.at(0, 1, 1) = Vec3d::Constant(1 / std::sqrt(3.0)) * (nseg > 2 ? 1.4 : 1.0);
  vm0.CopyEquiv();
  const ProfilePointFn<double> profile_point = [&](int i, int k, int ns) { return profiles[i].Point(spacing, k, ns); };
  VGrid<double> vm = SubdivideToSegments(vm0, nseg, profile_point, false);
  for (Vec3d& co : vm.co) co.normalize();
  return vm;
}

}  // namespace bevel
}  // namespace opgraph
