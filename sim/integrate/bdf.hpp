// Variable-step BDF coefficients, the Lagrange predictor and the local error constant
// (paper §3.2, eq. 23-24), all computed from the actual times of the step history.
//
// With t_0 = t_{k+1} the new time and t_1 = t_k, ..., t_s the s previous accepted times, let
// L_j be the Lagrange basis on t_0..t_s. Requiring the interpolant through x_0..x_s to have
// slope v_0 at t_0 gives sum_j L_j'(t_0) x_j = v_0; dividing by L_0'(t_0) yields eq. (23):
//     0 = x_{k+1} + sum_{j=1..s} alpha_j x_{k+1-j} - beta h v_{k+1},
//     alpha_j = L_j'(t_0) / L_0'(t_0),  beta h = 1 / L_0'(t_0),  h = t_0 - t_1.
// The predictor is the polynomial through the s+1 points t_1..t_{s+1}, evaluated at t_0.
// For a solution with smooth (s+1)-th derivative D = x^(s+1)/(s+1)!, the predictor error is
// x - x_pred = Cp D with Cp = prod_{m=1..s+1} (t_0 - t_m), and the corrector error is
// x - x_corr = Cc D with Cc = -prod_{m=1..s} (t_0 - t_m) / L_0'(t_0). Hence the local error
// of the corrector is estimated as  Cc / (Cp - Cc) * (x_corr - x_pred)  (Milne's device; for
// constant steps this is -(x_corr - x_pred) / ((s+1) H_s + 1), H_s the harmonic number).
#pragma once

#include <vector>

namespace crumple {

struct BdfCoefficients {
  int order = 0;
  std::vector<double> alpha;  ///< alpha[j-1] multiplies the value at times[j], j = 1..s
  double beta = 0;            ///< so that beta * h = 1 / L_0'(t_0)
  double h = 0;               ///< t_0 - t_1
};

/// times = {t_{k+1}, t_k, ..., t_{k+1-s}} (s+1 distinct values, newest first), s = order >= 1.
BdfCoefficients bdf_coefficients(const std::vector<double>& times);

/// Weights w_j of the Lagrange polynomial through the nodes, evaluated at t:
/// P(t) = sum_j w_j y_j. nodes are distinct.
std::vector<double> lagrange_weights(const std::vector<double>& nodes, double t);

/// Factor E such that the local error of the order-s corrector is E * (x_corr - x_pred), where
/// the predictor runs through times[1..s+1] (so times has s+2 entries, newest first).
double bdf_error_factor(const std::vector<double>& times);

/// Largest ratio h_new / h_old of consecutive steps for a step of order s (1..4; above 4 as 4).
///
/// Variable-step BDF is zero-stable only for bounded step ratios. On a grid whose ratio is a
/// constant w the coefficients of eq. (23) are the same at every step, and for x' = 0 the
/// recurrence x_{k+1} = -sum_j alpha_j x_{k+1-j} has, besides the root 1, s - 1 extraneous
/// roots; they reach the unit circle at w = 1 + sqrt(2) (s = 2), (1 + sqrt(5)) / 2 (s = 3) and
/// 1.2807 (s = 4). At w = 2, which the error controller allows, the largest extraneous root
/// of BDF4 has modulus 2.8: each doubling step amplifies the Newton and rounding errors almost
/// threefold. The limits below keep that modulus at or below 0.9 (w = 2.2, 1.5, 1.22; BDF1 has
/// no extraneous root). Measured cause of the limit: at 12000 nodes the radial confinement, on
/// its way back from an explicit phase, climbed to order 4 while doubling h, and the extraneous
/// mode grew into a spurious snap (kinetic energy x 400 within 0.3 ms) that sent the hybrid
/// back to the explicit mode, over and over.
double bdf_growth_limit(int order);

}  // namespace crumple
