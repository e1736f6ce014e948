// Forcing terms of the inexact Newton iteration (sim/integrate/forcing.hpp): the first
// iteration is solved to cg_tol, later ones to half the Newton tolerance relative to the last
// update, within [cg_tol, cg_tol_max].
#include "sim/integrate/forcing.hpp"

#include <gtest/gtest.h>

#include <limits>

using crumple::ForcingTerms;

TEST(Forcing, FirstIterationUsesTheTightTolerance) {
  const ForcingTerms f{1e-2, 1e-1, 0.1};
  EXPECT_EQ(f.at(1, 0.0), 1e-2);
  EXPECT_EQ(f.at(1, 0.3), 1e-2);  // k = 1 ignores any update (there is none yet)
  // No usable previous update: fall back to the tight tolerance.
  EXPECT_EQ(f.at(2, 0.0), 1e-2);
  EXPECT_EQ(f.at(2, std::numeric_limits<double>::quiet_NaN()), 1e-2);
}

TEST(Forcing, ScalesWithTheNewtonToleranceOverTheLastUpdate) {
  const ForcingTerms f{1e-3, 0.5, 0.1};
  EXPECT_NEAR(f.at(2, 1.0), 0.05, 1e-15);   // 0.5 * 0.1 / 1
  EXPECT_NEAR(f.at(3, 0.25), 0.2, 1e-15);   // a smaller update: a looser solve
  EXPECT_EQ(f.at(2, 1e-4), 0.5);            // nearly converged: capped at cg_tol_max
  EXPECT_EQ(f.at(2, 1e3), 1e-3);            // far from converged: floored at cg_tol
  const ForcingTerms g{1e-3, 0.5, 0.01};    // a tighter Newton test asks for tighter solves
  EXPECT_LT(g.at(2, 1.0), f.at(2, 1.0));
}

TEST(Forcing, EqualBoundsGiveAFixedTolerance) {
  const ForcingTerms f{1e-4, 1e-4, 0.1};
  for (const double update : {1e-3, 0.1, 1.0, 10.0}) EXPECT_EQ(f.at(2, update), 1e-4);
  EXPECT_EQ(f.at(1, 0.0), 1e-4);
}
