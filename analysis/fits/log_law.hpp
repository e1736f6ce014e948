// Fit of the logarithmic crease-length law l(n) = C ln(1 + n / n0) (statistics.md §2.2-2.3) by
// nonlinear least squares (a two-parameter Levenberg-Marquardt written out with Eigen), with the
// parameter covariance s^2 (J^T J)^-1 at the optimum, and conversion to the experiment's
// constants c1 = C / (1 - D), c2 = D / n0 when the compaction ratio D is known.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

struct LogLawFit {
  double C = 0.0, n0 = 0.0;            ///< fitted parameters (C in the units of l, n0 in cycles)
  double sigma_C = 0.0, sigma_n0 = 0.0; ///< 1-sigma uncertainties
  double corr = 0.0;                    ///< correlation coefficient of (C, n0)
  double rss = 0.0;                     ///< weighted residual sum of squares (chi^2 when sigmas given)
  int dof = 0;                          ///< points - 2
  double chi2_red = 0.0;                ///< rss / dof
  double r2 = 0.0;                      ///< coefficient of determination
  bool weighted = false;                ///< true when per-point sigmas were given
  int iterations = 0;
  bool converged = false;
};

/// Fits l_i = C ln(1 + n_i / n0) to (n_i, l_i), n_i > 0. With `sigma` (one per point, > 0) the
/// residuals are weighted and the covariance is (J^T W J)^-1 (absolute sigmas); without it the
/// covariance is scaled by the residual variance rss / (N - 2). Needs N >= 3 and some l_i > 0.
LogLawFit fit_log_law(const std::vector<double>& n, const std::vector<double>& l,
                      const std::vector<double>& sigma = {});

/// c1 = C/(1-D), c2 = D/n0 with first-order propagated 1-sigma errors (statistics.md §2.3).
struct ExperimentConstants {
  double c1 = 0, sigma_c1 = 0, c2 = 0, sigma_c2 = 0;
};
ExperimentConstants to_experiment_constants(const LogLawFit& fit, double compaction);

}  // namespace crumple::analysis
