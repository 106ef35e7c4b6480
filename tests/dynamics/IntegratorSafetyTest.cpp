// Integrators never hand on a non-finite state (the dense output's slopes can overflow where the step's end
// did not; a module's method may check nothing itself), and an adaptive method's error control is relative
// as well as absolute, so that a growing solution costs what it costs and does not crawl.
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/TimeSampler.h"
#include "dynamics/integrators/Verner9.h"
#include "tests/dynamics/TestModels.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace rv {
namespace {

const ModelInfo& growthInfo() {
  static const ModelInfo info{.id = "growth", .stateNames = {"x"}, .coreDimension = 1};
  return info;
}
// dx/dt = a x
struct Growth : ModelWithField<Growth, 1> {
  explicit Growth(double a) : ModelWithField(growthInfo(), ParameterValues(growthInfo().parameters)), a(a) {}
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const { dx[0] = a * x[0]; }
  double a;
};

// the case: Lorenz with rk4 at step 0.3 blows up between t = 0.9 and 1.2; the step that ends at 1.2
// is still finite (-1e217) but the dense output at t = 1 (its slopes overflow) was -inf, and was written
TEST(IntegratorSafety, ADenseOutputThatOverflowsIsAnErrorNotASample) {
  const auto lorenz = test::makeModel("lorenz", {});
  Rk4 rk4(0.3);
  rk4.start(*lorenz, 0, Eigen::Vector3d(1, 1, 1)); // the default scene's start
  std::vector<Eigen::VectorXd> seen;
  try {
    sampleUniform(rk4, 1, 3, [&](double, const Eigen::VectorXd& x) {
      seen.push_back(x);
      return true;
    });
    FAIL() << "the blow-up went unnoticed";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("stopped being finite"), std::string::npos) << e.what();
  }
  for (const auto& x : seen)
    EXPECT_TRUE(x.allFinite()) << x.transpose();
}

// a method as a module might write it: explicit Euler that checks nothing -- the base class does
class UncheckedEuler final : public Integrator {
public:
  explicit UncheckedEuler(double h) : h_(h) {}
  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) override {
    Integrator::start(model, t0, x0, direction);
    f_.resize(x0.size());
  }
  void step() override {
    xPrev_ = x_, tPrev_ = t_;
    evaluate(x_, f_);
    x_ += direction_ * h_ * f_;
    t_ += direction_ * h_;
  }
  void interpolate(double t, Eigen::VectorXd& out) const override {
    const double s = (t - tPrev_) / (t_ - tPrev_);
    out = (1 - s) * xPrev_ + s * x_;
  }

private:
  double h_;
  Eigen::VectorXd f_;
};

TEST(IntegratorSafety, AMethodThatChecksNothingStillHandsOnNoInfinity) {
  test::Blowup m;                    // y' = y^2 from 1: infinite at t = 1
  for (double every : {0.25, 0.3}) { // samples on step ends, and between them
    UncheckedEuler euler(0.05);
    Eigen::VectorXd x0(1);
    x0 << 1;
    euler.start(m, 0, x0, +1);
    std::vector<Eigen::VectorXd> seen;
    EXPECT_THROW(sampleUniform(euler, every, 1000,
                               [&](double, const Eigen::VectorXd& x) {
                                 seen.push_back(x);
                                 return true;
                               }),
                 ComputationError);
    ASSERT_FALSE(seen.empty());
    for (const auto& x : seen)
      EXPECT_TRUE(x.allFinite()) << "every = " << every;
  }
}

// dx/dt = x / 2 from 1: x(100) = e^50 ~ 5e21. An absolute error control alone shrinks the step towards
// min_step as x grows (the run did not end in 30 s); a relative one above |x| = 1 keeps it growing
TEST(IntegratorSafety, MersonFollowsAGrowingSolutionAtARelativeError) {
  const Growth m(0.5);
  Merson merson(1e-2, 1e-10, 1e-10, 0.1);
  Eigen::VectorXd x0(1);
  x0 << 1;
  merson.start(m, 0, x0);
  Eigen::VectorXd end;
  merson.advanceTo(100, end);
  EXPECT_NEAR(end[0] / std::exp(50.0), 1, 1e-7);
  // about what t = 100 costs at steps near the largest (0.1): a few thousand steps of five evaluations (an
  // absolute control alone needed millions)
  EXPECT_LT(merson.evaluations(), 20000);
}

// below |x| = 1 the control is the manual's absolute precision, unchanged: the same steps as before
TEST(IntegratorSafety, MersonKeepsTheAbsolutePrecisionBelowOne) {
  const Growth m(-0.5);
  Merson merson(1e-2, 1e-10, 1e-10, 0.1);
  Eigen::VectorXd x0(1);
  x0 << 0.5;
  merson.start(m, 0, x0);
  Eigen::VectorXd end;
  merson.advanceTo(10, end);
  EXPECT_NEAR(end[0], 0.5 * std::exp(-5.0), 1e-9);
}

} // namespace
} // namespace rv
