// Anderson acceleration against fixed-point maps whose fixed point is known: on a slowly
// contracting linear map (the case of the correspondence loop near its end) it reaches the
// fixed point in a few steps where plain iteration takes hundreds, and it never proposes a
// point before it has two applications to extrapolate from.
#include "solver/anderson.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace opgraph {
namespace {

// G(x) = A x + b, contraction rates 0.97, 0.9 and 0.5 along a rotated basis; fixed point x*.
struct SlowLinearMap {
  SlowLinearMap() {
    Eigen::Matrix3d basis = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    a = basis * Eigen::Vector3d(0.97, 0.9, 0.5).asDiagonal() * basis.transpose();
    fixed_point = Eigen::Vector3d(0.3, -1.2, 2.5);
    b = fixed_point - a * fixed_point;
  }
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return a * x + b; }
  Eigen::Matrix3d a;
  Eigen::Vector3d b, fixed_point;
};

// Steps until |x - x*| < tolerance, at most `limit`.
int StepsToFixedPoint(int history, int limit) {
  const SlowLinearMap map;
  AndersonAcceleration anderson(history);
  Eigen::VectorXd x = Eigen::Vector3d(5, 5, 5);
  for (int step = 1; step <= limit; ++step) {
    const Eigen::VectorXd image = map(x);
    Eigen::VectorXd next;
    x = anderson.Step(x, image, &next) ? next : image;
    if ((x - map.fixed_point).norm() < 1e-9) return step;
  }
  return limit + 1;
}

TEST(Anderson, ReachesTheFixedPointOfASlowLinearMapInFewSteps) {
  const int plain = StepsToFixedPoint(0, 2000);
  const int accelerated = StepsToFixedPoint(3, 2000);
  EXPECT_GT(plain, 500);  // 0.97^k * 8.7 < 1e-9 needs k of about 750
  // On a linear map of dimension n, Anderson with n stored differences is GMRES: exact after
  // n + 1 extrapolations, up to rounding.
  EXPECT_LE(accelerated, 8);
}

TEST(Anderson, ProposesNothingUntilTwoApplicationsOrWhenOff) {
  const SlowLinearMap map;
  Eigen::VectorXd x = Eigen::Vector3d(1, 1, 1), next;
  AndersonAcceleration off(0);
  EXPECT_FALSE(off.Step(x, map(x), &next));
  AndersonAcceleration on(2);
  EXPECT_FALSE(on.Step(x, map(x), &next));
  const Eigen::VectorXd image = map(x);
  EXPECT_TRUE(on.Step(image, map(image), &next));
  on.Clear();
  EXPECT_FALSE(on.Step(x, map(x), &next));
}

}  // namespace
}  // namespace opgraph
