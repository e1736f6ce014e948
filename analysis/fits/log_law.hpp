// Fit of the logarithmic crease-length law l(n) = C ln(1 + n / n0) (docs/STATISTICS.md §2.2-2.3)
// by nonlinear least squares (C eliminated exactly, n0 found by a scan and Brent's method; see
// log_law.cpp), with the parameter covariance at the optimum, and conversion to the experiment's
// constants c1 = C / (1 - D), c2 = D / n0 when the compaction ratio D is known. This is the one
// implementation of the law's fit: crumple-analyze fits each run with it, and
// `crumple-analyze ensemble` the means over runs (analysis/ensemble/).
//
// Two fits of the same law. The cumulative fit takes l_n itself; but l_n is the sum of all
// earlier cycles' increments, so its deviations from the law are correlated from cycle to cycle
// (a random walk), and the least-squares covariance, which assumes independent residuals,
// understates the uncertainty of (C, n0) and makes chi^2 look small. The increment fit takes
// dl_n = l_n - l_(n-1) = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)]: the new creases of different
// cycles are made by different crumples, so the increments are nearly independent (a per-cycle
// measurement error, such as the rasterisation of P, still anti-correlates neighbours a little)
// and its covariance is the honest one (docs/STATISTICS.md §2.3, step 4).
//
// The search is confined to C >= 0 and kN0Min <= n0 <= kN0Max. Data that do not bend (n0 -> oo:
// a straight line of slope C/n0) or that put all the length into the first cycle (n0 -> 0) have
// their least-squares optimum at no finite n0; the fit then stops on the bound, says so
// (at_bound), and keeps the covariance of the full Jacobian there, whose huge sigma_n0 shows that
// the data do not fix n0. (The range is the one the ensemble fits of pipeline/plots/ensemble.py
// had in scipy's curve_fit before they moved here, issue 34.)
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

/// The range of n0 (cycles) the fit searches; far outside the cycles fitted, n0 is not
/// determined by them.
inline constexpr double kN0Min = 1e-6, kN0Max = 1e6;

struct LogLawFit {
  double C = 0.0, n0 = 0.0;            ///< fitted parameters (C in the units of l, n0 in cycles)
  double sigma_C = 0.0, sigma_n0 = 0.0; ///< 1-sigma uncertainties
  double corr = 0.0;                    ///< correlation coefficient of (C, n0)
  double rss = 0.0;                     ///< weighted residual sum of squares (chi^2 when sigmas given)
  int dof = 0;                          ///< points - 2
  double chi2_red = 0.0;                ///< rss / dof
  double r2 = 0.0;                      ///< coefficient of determination
  bool weighted = false;                ///< true when per-point sigmas were given
  int iterations = 0;                   ///< of the one-dimensional search for n0
  bool converged = false;
  bool at_bound = false;                ///< stopped on C = 0, n0 = kN0Min or n0 = kN0Max
  std::string model;                    ///< which form was fitted, in words
};

/// Fits l_i = C ln(1 + n_i / n0) to (n_i, l_i), n_i > 0. With `sigma` (one per point, > 0) the
/// residuals are weighted and the covariance is (J^T W J)^-1 (absolute sigmas); without it the
/// covariance is scaled by the residual variance rss / (N - 2). Needs N >= 3 and some l_i > 0.
LogLawFit fit_log_law(const std::vector<double>& n, const std::vector<double>& l,
                      const std::vector<double>& sigma = {});

/// Fits dl_i = C [ln(1 + n_i/n0) - ln(1 + m_i/n0)] to increments dl_i between cycles m_i and
/// n_i (0 <= m_i < n_i; m_i = n_i - 1 for consecutive cycles, m = 0 before the first). Same
/// covariance rules as fit_log_law; needs N >= 3 increments and some dl_i > 0.
LogLawFit fit_log_law_increments(const std::vector<double>& n_from,
                                 const std::vector<double>& n_to, const std::vector<double>& dl,
                                 const std::vector<double>& sigma = {});

/// c1 = C/(1-D), c2 = D/n0 with first-order propagated 1-sigma errors (docs/STATISTICS.md §2.3).
struct ExperimentConstants {
  double c1 = 0, sigma_c1 = 0, c2 = 0, sigma_c2 = 0;
};
ExperimentConstants to_experiment_constants(const LogLawFit& fit, double compaction);

/// The law over several compaction ratios, fitted globally (the collapse, docs/STATISTICS.md
/// §2.3 step 4): dl_i = c1 (1 - D_i) [ln(1 + c2 n_i/D_i) - ln(1 + c2 m_i/D_i)] for the
/// increments dl_i between cycles m_i < n_i of a sheet crumpled to D_i (m_i = 0 and dl_i = l_i:
/// the cumulative form). The same solver as fit_log_law (c1 exact, c2 = 1/n0 searched within
/// [1/kN0Max, 1/kN0Min]) and the same covariance rules; the errors of c2 are propagated from
/// those of n0.
struct CollapseFit {
  double c1 = 0, sigma_c1 = 0, c2 = 0, sigma_c2 = 0, corr = 0;
  double chi2 = 0, chi2_red = 0;
  int dof = 0, points = 0;
  bool weighted = false, converged = false, at_bound = false;
};
CollapseFit fit_collapse(const std::vector<double>& compaction, const std::vector<double>& n_from,
                         const std::vector<double>& n_to, const std::vector<double>& dl,
                         const std::vector<double>& sigma = {});

}  // namespace crumple::analysis
