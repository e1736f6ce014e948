// The plastic flow law (sim/integrate/plasticity.hpp, paper eq. 17-20): dead band, sign,
// continuity, saturation, and its derivative against finite differences.
#include "sim/integrate/plasticity.hpp"

#include <gtest/gtest.h>

#include <cmath>

using crumple::PlasticLaw;

TEST(Plasticity, SmoothstepEndsAndMidpoint) {
  EXPECT_EQ(PlasticLaw::smoothstep(-0.5), 0.0);
  EXPECT_EQ(PlasticLaw::smoothstep(0.0), 0.0);
  EXPECT_DOUBLE_EQ(PlasticLaw::smoothstep(0.5), 0.5);
  EXPECT_EQ(PlasticLaw::smoothstep(1.0), 1.0);
  EXPECT_EQ(PlasticLaw::smoothstep(3.0), 1.0);
  // C2 at both ends: S' and S'' vanish there.
  EXPECT_EQ(PlasticLaw::smoothstep_derivative(0.0), 0.0);
  EXPECT_EQ(PlasticLaw::smoothstep_derivative(1.0), 0.0);
  EXPECT_NEAR(PlasticLaw::smoothstep_derivative(1e-4), 0.0, 1e-6);
}

TEST(Plasticity, DeadBandSignAndSaturation) {
  PlasticLaw law{0.3, 1.0, 2.0, true};  // c0, gamma, rate
  // No flow while |c - p| < c0, whichever the sign.
  for (double u : {-0.29, -0.1, 0.0, 0.1, 0.29}) {
    EXPECT_EQ(law.g(0.5 + u, 0.5), 0.0) << u;
    EXPECT_EQ(law.dg_dc(0.5 + u, 0.5), 0.0) << u;
  }
  // Flow towards c above the yield curvature; odd in c - p.
  EXPECT_GT(law.g(1.0, 0.2), 0.0);
  EXPECT_LT(law.g(-0.6, 0.2), 0.0);
  EXPECT_NEAR(law.g(0.2 + 0.9, 0.2), -law.g(0.2 - 0.9, 0.2), 1e-12);
  // Saturates at rate / (1 + gamma) when |c - p| reaches 2.
  EXPECT_DOUBLE_EQ(law.g(1.0, -1.0), 2.0 / 2.0);
  // Disabled: nothing flows.
  PlasticLaw off = law;
  off.enabled = false;
  EXPECT_EQ(off.g(1.0, -1.0), 0.0);
  EXPECT_EQ(off.dg_dc(1.0, -0.2), 0.0);
}

TEST(Plasticity, DerivativeMatchesFiniteDifferences) {
  PlasticLaw law{0.2, 0.5, 3.0, true};
  const double eps = 1e-6;
  for (double p : {-0.7, 0.0, 0.4})
    for (double u = -1.9; u <= 1.9; u += 0.173) {
      const double c = p + u;
      const double fd_c = (law.g(c + eps, p) - law.g(c - eps, p)) / (2 * eps);
      const double fd_p = (law.g(c, p + eps) - law.g(c, p - eps)) / (2 * eps);
      EXPECT_NEAR(law.dg_dc(c, p), fd_c, 1e-6) << c << " " << p;
      EXPECT_NEAR(-law.dg_dc(c, p), fd_p, 1e-6) << c << " " << p;
      EXPECT_GE(law.dg_dc(c, p), 0.0);
    }
}
