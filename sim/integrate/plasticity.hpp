// The plastic flow law of the rest curvature (paper §2.5, eq. 17-20), kept behind one struct
// so that its form can be changed in one place (docs/MODEL.md §7).
//
// For a hinge with current curvature c = 2 sin(theta/2) and rest curvature p,
//     dp/dt = g(c, p) = rate * sgn(c - p) f(|c - p|),
//     f(lambda) = S((lambda - c0) / (2 - c0)) / (1 + gamma),
//     S(x) = 6x^5 - 15x^4 + 10x^3 clamped to [0, 1] (quintic smoothstep, eq. 20).
// c0 is the yield curvature: nothing flows while |c - p| < c0 (the dead band), so g is
// continuous and vanishes on a whole interval around c = p; gamma slows the flow. The paper's
// f is dimensionless as printed; `rate` (1/s) gives the flow its time scale, so that
// dp/dt = rate at full yield (|c - p| = 2, gamma = 0).
// Derivatives: dg/dc = rate f'(|c - p|) >= 0 and dg/dp = -dg/dc (g depends on c - p only).
#pragma once

namespace crumple {

struct PlasticLaw {
  double c0 = 0.1;      ///< yield curvature, 0 <= c0 < 2
  double gamma = 0.0;   ///< damage-rate constant, >= 0
  double rate = 1.0;    ///< 1/s, multiplies f
  bool enabled = true;  ///< false: p never changes (g = 0)

  /// Quintic smoothstep S(x), clamped to [0, 1] outside [0, 1].
  static double smoothstep(double x);
  /// dS/dx (zero outside [0, 1]).
  static double smoothstep_derivative(double x);

  /// f(lambda) (eq. 19), times rate; lambda = |c - p| >= 0.
  double f(double lambda) const;
  /// df/dlambda, times rate.
  double df(double lambda) const;

  /// g(c, p) = dp/dt (eq. 18).
  double g(double c, double p) const;
  /// dg/dc = rate f'(|c - p|) >= 0; dg/dp is its negative.
  double dg_dc(double c, double p) const;
};

}  // namespace crumple
