// The dense Levenberg-Marquardt against references it was not tuned on: known parameters of a
// noise-free model recovered exactly, Ceres' own Levenberg-Marquardt on the same noisy problem
// (same minimum), a bound that holds at the constrained minimum, a point where the problem
// cannot be evaluated, and the fitter's normal equations against finite differences.
#include "solver/dense_lm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <ceres/ceres.h>

namespace opgraph {
namespace {

// y = a exp(b t) + c sin(d t): 4 parameters, 200 residuals.
struct CurveResidual {
  CurveResidual(double t, double y) : t(t), y(y) {}
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    residual[0] = p[0] * exp(p[1] * t) + p[2] * sin(p[3] * t) - y;
    return true;
  }
  static ceres::CostFunction* Create(double t, double y) {
    return new ceres::AutoDiffCostFunction<CurveResidual, 1, 4>(new CurveResidual(t, y));
  }
  double t, y;
};

struct Samples {
  std::vector<double> t, y;
};

Samples MakeSamples(const Eigen::Vector4d& truth, double noise) {
  std::mt19937 random(7);
  std::normal_distribution<double> gaussian(0, noise);
  Samples samples;
  for (int i = 0; i < 200; ++i) {
    const double t = i / 100.0;
    samples.t.push_back(t);
    samples.y.push_back(truth[0] * std::exp(truth[1] * t) + truth[2] * std::sin(truth[3] * t) + gaussian(random));
  }
  return samples;
}

class CurveProblem : public DenseLmProblem {
 public:
  explicit CurveProblem(const Samples& samples) : samples_(samples) {}
  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) override {
    if (x[0] < -50) return std::numeric_limits<double>::infinity();  // "cannot be evaluated" there
    double cost = 0;
    if (jtj) jtj->setZero(), jtr->setZero();
    for (size_t i = 0; i < samples_.t.size(); ++i) {
      const double t = samples_.t[i], e = std::exp(x[1] * t), s = std::sin(x[3] * t);
      const double r = x[0] * e + x[2] * s - samples_.y[i];
      cost += r * r;
      if (!jtj) continue;
      const Eigen::Vector4d row(e, x[0] * t * e, s, x[2] * t * std::cos(x[3] * t));
      *jtj += row * row.transpose();
      *jtr += row * r;
    }
    return cost;
  }

 private:
  Samples samples_;  // a copy: callers pass temporaries
};

Eigen::VectorXd Minimize(const Samples& samples, Eigen::VectorXd lower, Eigen::VectorXd upper, Eigen::VectorXd x,
                         DenseLmSummary* summary, int iterations = 100) {
  CurveProblem problem(samples);
  DenseLmOptions options;
  options.max_iterations = iterations;
  options.initial_radius = 1e4;
  *summary = MinimizeDenseLm(&problem, lower, upper, options, &x);
  return x;
}

const Eigen::Vector4d kTruth(1.5, -0.8, 0.7, 3.0);
const Eigen::Vector4d kStart(1.0, -0.5, 1.0, 2.6);
const Eigen::VectorXd kUnbounded = Eigen::VectorXd::Constant(4, std::numeric_limits<double>::infinity());

TEST(DenseLm, RecoversKnownParametersExactly) {
  DenseLmSummary summary;
  const Eigen::VectorXd x = Minimize(MakeSamples(kTruth, 0), -kUnbounded, kUnbounded, kStart, &summary);
  EXPECT_LT((x - kTruth).cwiseAbs().maxCoeff(), 1e-7) << x.transpose();
  EXPECT_LT(summary.final_cost, 1e-20);
  EXPECT_GT(summary.initial_cost, 1.0);
}

TEST(DenseLm, ReachesCeresMinimumOnNoisyData) {
  const Samples samples = MakeSamples(kTruth, 0.05);
  DenseLmSummary summary;
  const Eigen::VectorXd ours = Minimize(samples, -kUnbounded, kUnbounded, kStart, &summary);
  double reference[4] = {kStart[0], kStart[1], kStart[2], kStart[3]};
  ceres::Problem problem;
  for (size_t i = 0; i < samples.t.size(); ++i) {
    problem.AddResidualBlock(CurveResidual::Create(samples.t[i], samples.y[i]), nullptr, reference);
  }
  ceres::Solver::Options options;
  options.function_tolerance = options.parameter_tolerance = options.gradient_tolerance = 1e-15;
  options.max_num_iterations = 200;
  ceres::Solver::Summary ceres_summary;
  ceres::Solve(options, &problem, &ceres_summary);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(ours[k], reference[k], 1e-6) << k;
  EXPECT_NEAR(summary.final_cost, 2 * ceres_summary.final_cost, 1e-9 * summary.final_cost);
  EXPECT_GT((ours - kTruth).norm(), 0);  // the noise moved the minimum: not a copy of the truth
}

TEST(DenseLm, HoldsTheBoxAndStopsAtTheConstrainedMinimum) {
  // Amplitude a capped below its true value: the minimum sits on the bound, and the others
  // compensate as well as they can.
  Eigen::VectorXd upper = kUnbounded;
  upper[0] = 1.2;
  DenseLmSummary summary;
  const Eigen::VectorXd x = Minimize(MakeSamples(kTruth, 0), -kUnbounded, upper, kStart, &summary);
  EXPECT_DOUBLE_EQ(x[0], 1.2);
  EXPECT_GT(summary.final_cost, 1e-6);
  // Any feasible move from there costs more (a first-order check in each direction).
  CurveProblem problem(MakeSamples(kTruth, 0));
  for (int k = 0; k < 4; ++k) {
    for (double h : {-1e-5, 1e-5}) {
      Eigen::VectorXd moved = x;
      moved[k] += h;
      if (moved[0] > 1.2) continue;
      EXPECT_GE(problem.Evaluate(moved, nullptr, nullptr), summary.final_cost * (1 - 1e-12)) << k << " " << h;
    }
  }
}

TEST(DenseLm, StepsWhereTheProblemFailsAreRejected) {
  // From far away with a huge radius, early steps land where Evaluate fails (a < -50); they
  // count as unsuccessful and the radius shrinks until steps succeed.
  DenseLmSummary summary;
  Eigen::VectorXd start = kStart;
  start[0] = -45;
  const Eigen::VectorXd x = Minimize(MakeSamples(kTruth, 0), -kUnbounded, kUnbounded, start, &summary, 300);
  EXPECT_TRUE(std::isfinite(summary.final_cost));
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  EXPECT_GE(x[0], -50);
}

TEST(DenseLm, StopsAfterMaxIterationsWithItsRadius) {
  DenseLmSummary summary;
  Minimize(MakeSamples(kTruth, 0), -kUnbounded, kUnbounded, kStart, &summary, 2);
  EXPECT_EQ(summary.iterations, 2);
  EXPECT_GT(summary.radius, 0);
  EXPECT_EQ(summary.jacobian_evaluations, 1 + summary.successful_steps);
}

}  // namespace
}  // namespace opgraph
