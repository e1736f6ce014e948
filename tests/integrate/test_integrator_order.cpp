// Convergence order of the integrator's own quasistatic steps (sim/integrate/integrator.hpp,
// paper eq. 22-35): the Lagrange predictor over the stored history, the BDF residuals with the
// reduced Newton solve and the acceptance path, on a smooth nonlinear problem with fixed steps.
// test_bdf.cpp checks the coefficients alone on a scalar equation; this runs the whole step.
//
// The problem: a stretched and bent 6 x 6 sheet relaxing under isotropic drag, 0 = F(x) - b v,
// i.e. the gradient flow x' = F(x) / b of springs and hinges (plasticity off: p constant).
// Fixed steps come from h_min = h_max = h with error tolerances loose enough that no step is
// rejected; Newton is solved to round-off with the direct solver. The history of each run is
// seeded with a reference solution at t0 - k h, so no start-up at lower order pollutes the
// error, and every step runs at bdf_order (checked in the step log).
#include "sim/integrate/integrator.hpp"
#include "tests/integrate/small_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace crumple;

namespace {

const Mesh& sheet() { return crumple::testing::small_sheet(); }
ModelParams params() { return crumple::testing::small_sheet_params(2.0); }
// Stretched by 5 % and bent, so that both stretching and bending relax over [0, T].
State start(const SheetModel& model) { return crumple::testing::stretched_and_bent(model); }

IntegratorSettings quasistatic(int order) {
  IntegratorSettings st;
  st.mode_initial = IntegrationMode::Implicit;
  st.switch_min_steps = 1 << 30;
  st.plasticity = false;
  st.linear_solver = LinearSolverKind::DirectLDLT;
  st.bdf_order = order;
  return st;
}

constexpr double kGrid = 0.0125;  // the finest fixed step; reference states on its multiples
constexpr double kT0 = 0.5, kT1 = 1.5;

// The reference solution on the grid j * kGrid, j = 0 .. kT1 / kGrid, by adaptive BDF4 with
// tolerances far below the fixed-step errors (each grid time is an exact landing point).
const std::vector<State>& reference() {
  static const std::vector<State> ref = [] {
    SheetModel model(sheet(), params());
    IntegratorSettings st = quasistatic(4);
    st.rtol = 1e-12;
    st.atol = 1e-14;
    st.h_init = 1e-7;
    st.h_min = 1e-16;  // below a config's floor: the start-up at rtol 1e-12 needs it
    Integrator integ(model, st);
    std::vector<State> out{start(model)};
    State s = out.front();
    const int n = static_cast<int>(std::lround(kT1 / kGrid));
    for (int j = 1; j <= n; ++j) {
      integ.advance_to(s, j * kGrid);
      out.push_back(s);
    }
    const auto sum = integ.summary();
    std::printf("reference: %ld steps, %ld rejected (error %ld, Newton %ld)\n", sum.steps(),
                sum.rejections(), sum.rejected_error, sum.rejected_newton);
    return out;
  }();
  return ref;
}

const State& reference_at(double t) {
  return reference().at(static_cast<std::size_t>(std::lround(t / kGrid)));
}

// Fixed steps h of BDF `order` over [kT0, kT1] from the reference history; returns the largest
// coordinate error at kT1.
double fixed_step_error(int order, double h) {
  SheetModel model(sheet(), params());
  IntegratorSettings st = quasistatic(order);
  st.h_init = st.h_min = st.h_max = h;
  st.rtol = st.atol = 1.0;  // no error-test rejection at these h
  st.newton_tol = 1e-10;    // in units of atol + rtol |x|: Newton to round-off
  Integrator integ(model, st);
  IntegratorHistory hist;
  for (int k = 0; k <= order; ++k) {  // the corrector needs `order` points, the predictor one more
    const State& r = reference_at(kT0 - k * h);
    hist.times.push_back(kT0 - k * h);
    hist.xs.push_back(r.x);
    hist.vs.push_back(r.v);
    hist.ps.push_back(r.p);
  }
  hist.times[0] = kT0;
  hist.h = h;
  hist.mode = IntegrationMode::Implicit;
  integ.restore(hist);
  State s = reference_at(kT0);
  integ.advance_to(s, kT1);
  const auto sum = integ.summary();
  EXPECT_EQ(sum.rejections(), 0) << "BDF" << order << " h = " << h;
  EXPECT_EQ(sum.steps_explicit, 0);
  EXPECT_EQ(static_cast<double>(integ.log().size()), std::round((kT1 - kT0) / h));
  for (const auto& row : integ.log()) {
    EXPECT_EQ(row.order, order) << "t = " << row.t;
    EXPECT_NEAR(row.h, h, 1e-12 * h) << "t = " << row.t;
  }
  return (s.x - reference_at(kT1).x).cwiseAbs().maxCoeff();
}

}  // namespace

TEST(IntegratorOrder, FixedStepBdf3AndBdf4ConvergeAtTheirOrder) {
  for (int order : {3, 4}) {
    const double e1 = fixed_step_error(order, 4 * kGrid), e2 = fixed_step_error(order, 2 * kGrid),
                 e3 = fixed_step_error(order, kGrid);
    const double expect = std::pow(2.0, order);
    std::printf("integrator BDF%d, h = %g, %g, %g: max error %.3e, %.3e, %.3e; ratios %.2f, %.2f "
                "(expect %.0f)\n", order, 4 * kGrid, 2 * kGrid, kGrid, e1, e2, e3, e1 / e2, e2 / e3,
                expect);
    EXPECT_NEAR(e2 / e3, expect, 0.15 * expect);
    EXPECT_NEAR(e1 / e2, expect, 0.25 * expect);  // the coarsest pair, further from asymptotic
  }
}
