// Least-squares fit of l = C ln(1 + n/n0) and of its increments; see log_law.hpp.
//
// Both fits share one problem: y_i = C [ln(1 + n_i/n0) - ln(1 + m_i/n0)], with m_i = 0 for the
// cumulative law and m_i = the previous cycle for the increments. The model is linear in C, so C
// is eliminated exactly (variable projection): for each n0 the best C >= 0 is a weighted linear
// least-squares solution, and chi^2 is minimised over u = ln n0 alone, first by a scan of u over
// [ln kN0Min, ln kN0Max], then by Brent's method between the neighbours of the best scan point.
// A two-parameter Levenberg-Marquardt on (C, u), which this replaced, crawls along the curved
// valley C/n0 = const of data that barely bend and stopped there at arbitrary n0 (5e4 where the
// optimum is n0 -> oo); the one-dimensional search reaches the bound. The reported covariance
// is computed afterwards from the Jacobian in (C, n0) at the optimum.
#include "analysis/fits/log_law.hpp"

#include "analysis/fits/minimize_1d.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace crumple::analysis {
namespace {

// The collapse over several compaction ratios D_i has the same form with per-point factors:
// y_i = c1 (1 - D_i) [ln(1 + c2 n_i/D_i) - ln(1 + c2 m_i/D_i)] is C s_i [ln(1 + n'_i/n0) -
// ln(1 + m'_i/n0)] with C = c1, n0 = 1/c2, s_i = 1 - D_i and n'_i = n_i/D_i, m'_i = m_i/D_i, so
// both fits are one solver (s = 1 and unscaled cycles for a single compaction).
struct Problem {
  Eigen::ArrayXd m, n, l, w;  // from, to, data, w = 1/sigma
  Eigen::ArrayXd s;           // per-point factor of C (ones for a single compaction)

  Eigen::ArrayXd basis(double n0) const {
    return s * ((1.0 + n / n0).log() - (1.0 + m / n0).log());
  }
  Eigen::ArrayXd model(double C, double n0) const { return C * basis(n0); }
  double rss(double C, double n0) const { return ((model(C, n0) - l) * w).square().sum(); }

  /// Weighted Jacobian of the model with respect to (C, n0).
  Eigen::MatrixX2d jacobian(double C, double n0) const {
    Eigen::MatrixX2d J(n.size(), 2);
    J.col(0) = (basis(n0) * w).matrix();
    J.col(1) = (-C * s * (n / (n0 * (n0 + n)) - m / (n0 * (n0 + m))) * w).matrix();
    return J;
  }

  /// Best C >= 0 for fixed n0: the model is linear in C.
  double best_C(double n0) const {
    const Eigen::ArrayXd g = basis(n0) * w;
    return std::max((g * l * w).sum() / g.square().sum(), 0.0);
  }
  /// chi^2 with C eliminated: the profile over u = ln n0.
  double profile(double u) const { return rss(best_C(std::exp(u)), std::exp(u)); }
};

LogLawFit solve(Problem& P, const std::vector<double>& sigma) {
  const Eigen::Index N = P.n.size();
  if (!sigma.empty()) {
    P.w = 1.0 / Eigen::Map<const Eigen::ArrayXd>(sigma.data(), N);
    if (!(P.w.isFinite().all() && (P.w > 0).all()))
      throw std::invalid_argument("fit_log_law: sigmas must be positive");
  }
  // Scan u = ln n0 over the whole range, 20 points a decade, so the search starts in the right
  // basin even when the data barely bend; then refine between the best point's neighbours.
  const double u_min = std::log(kN0Min), u_max = std::log(kN0Max);
  const int K = static_cast<int>(std::lround(20 * std::log10(kN0Max / kN0Min)));
  const auto u_at = [&](int i) { return u_min + i * (u_max - u_min) / K; };
  int best = 0;
  double best_r = INFINITY;
  for (int i = 0; i <= K; ++i) {
    const double r = P.profile(u_at(i));
    if (r < best_r) best_r = r, best = i;
  }
  LogLawFit fit;
  const auto f = [&](double x) { return P.profile(x); };
  double u = u_at(best);
  if (best == 0 || best == K) {
    // The best scan point is a bound: the minimum is there unless it lies inside the last
    // interval, which Brent's method finds from that interval's midpoint.
    const double a = u_at(best == 0 ? 0 : K - 1), b = u_at(best == 0 ? 1 : K);
    const double mid = 0.5 * (a + b);
    if (f(mid) < best_r)
      u = brent_minimize(f, a, b, mid, fit.iterations, fit.converged);
    else
      fit.converged = true;
  } else {
    u = brent_minimize(f, u_at(best - 1), u_at(best + 1), u, fit.iterations, fit.converged);
  }
  // Brent's method never evaluates the ends of its bracket: a minimum on a bound is taken there.
  for (const double edge : {u_min, u_max})
    if (std::abs(u - edge) < 1e-6 && f(edge) <= f(u)) u = edge;
  const double C = P.best_C(std::exp(u)), cur = P.profile(u);
  fit.C = C;
  fit.n0 = std::exp(u);
  fit.at_bound = C <= 0.0 || u == u_min || u == u_max;
  fit.rss = cur;
  fit.dof = static_cast<int>(N) - 2;
  fit.chi2_red = fit.dof > 0 ? cur / fit.dof : 0.0;
  fit.weighted = !sigma.empty();
  const Eigen::MatrixX2d J = P.jacobian(fit.C, fit.n0);
  Eigen::Matrix2d cov = (J.transpose() * J).inverse();
  if (!fit.weighted) cov *= fit.chi2_red;
  fit.sigma_C = std::sqrt(cov(0, 0));
  fit.sigma_n0 = std::sqrt(cov(1, 1));
  fit.corr = cov(0, 1) / (fit.sigma_C * fit.sigma_n0);
  const Eigen::ArrayXd lw = P.l * P.w;
  const double wmean = (lw * P.w).sum() / P.w.square().sum();
  const double tss = ((P.l - wmean) * P.w).square().sum();
  fit.r2 = tss > 0 ? 1.0 - cur / tss : 0.0;
  return fit;
}

}  // namespace

LogLawFit fit_log_law(const std::vector<double>& n, const std::vector<double>& l,
                      const std::vector<double>& sigma) {
  const auto N = static_cast<Eigen::Index>(n.size());
  if (n.size() != l.size() || (!sigma.empty() && sigma.size() != n.size()))
    throw std::invalid_argument("fit_log_law: n, l (and sigma) must have equal lengths");
  if (N < 3) throw std::invalid_argument("fit_log_law: need at least 3 points");
  Problem P{Eigen::ArrayXd::Zero(N), Eigen::Map<const Eigen::ArrayXd>(n.data(), N),
            Eigen::Map<const Eigen::ArrayXd>(l.data(), N), Eigen::ArrayXd::Ones(N),
            Eigen::ArrayXd::Ones(N)};
  if ((P.n <= 0).any()) throw std::invalid_argument("fit_log_law: cycle numbers must be > 0");
  if (!(P.l > 0).any()) throw std::invalid_argument("fit_log_law: all lengths are zero");
  LogLawFit fit = solve(P, sigma);
  fit.model = "l = C ln(1 + n/n0), fitted to the cumulative lengths";
  return fit;
}

LogLawFit fit_log_law_increments(const std::vector<double>& n_from,
                                 const std::vector<double>& n_to, const std::vector<double>& dl,
                                 const std::vector<double>& sigma) {
  const auto N = static_cast<Eigen::Index>(n_to.size());
  if (n_from.size() != n_to.size() || dl.size() != n_to.size() ||
      (!sigma.empty() && sigma.size() != n_to.size()))
    throw std::invalid_argument("fit_log_law_increments: inputs must have equal lengths");
  if (N < 3) throw std::invalid_argument("fit_log_law_increments: need at least 3 increments");
  Problem P{Eigen::Map<const Eigen::ArrayXd>(n_from.data(), N),
            Eigen::Map<const Eigen::ArrayXd>(n_to.data(), N),
            Eigen::Map<const Eigen::ArrayXd>(dl.data(), N), Eigen::ArrayXd::Ones(N),
            Eigen::ArrayXd::Ones(N)};
  if ((P.m < 0).any() || (P.n <= P.m).any())
    throw std::invalid_argument("fit_log_law_increments: need 0 <= n_from < n_to");
  if (!(P.l > 0).any())
    throw std::invalid_argument("fit_log_law_increments: no positive increment");
  LogLawFit fit = solve(P, sigma);
  fit.model = "dl_n = l_n - l_(n-1) = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)], fitted to the "
              "per-cycle increments";
  return fit;
}

ExperimentConstants to_experiment_constants(const LogLawFit& fit, double D) {
  if (!(D > 0 && D < 1)) throw std::invalid_argument("compaction must lie in (0, 1)");
  ExperimentConstants k;
  k.c1 = fit.C / (1.0 - D);
  k.sigma_c1 = fit.sigma_C / (1.0 - D);
  k.c2 = D / fit.n0;
  k.sigma_c2 = D * fit.sigma_n0 / (fit.n0 * fit.n0);
  return k;
}

CollapseFit fit_collapse(const std::vector<double>& compaction, const std::vector<double>& n_from,
                         const std::vector<double>& n_to, const std::vector<double>& dl,
                         const std::vector<double>& sigma) {
  const auto N = static_cast<Eigen::Index>(n_to.size());
  if (compaction.size() != n_to.size() || n_from.size() != n_to.size() ||
      dl.size() != n_to.size() || (!sigma.empty() && sigma.size() != n_to.size()))
    throw std::invalid_argument("fit_collapse: inputs must have equal lengths");
  if (N < 3) throw std::invalid_argument("fit_collapse: need at least 3 increments");
  const Eigen::ArrayXd D = Eigen::Map<const Eigen::ArrayXd>(compaction.data(), N);
  if (!((D > 0).all() && (D < 1).all()))
    throw std::invalid_argument("fit_collapse: compaction ratios must lie in (0, 1)");
  Problem P{Eigen::Map<const Eigen::ArrayXd>(n_from.data(), N) / D,
            Eigen::Map<const Eigen::ArrayXd>(n_to.data(), N) / D,
            Eigen::Map<const Eigen::ArrayXd>(dl.data(), N), Eigen::ArrayXd::Ones(N), 1.0 - D};
  if ((P.m < 0).any() || (P.n <= P.m).any())
    throw std::invalid_argument("fit_collapse: need 0 <= n_from < n_to");
  if (!(P.l > 0).any()) throw std::invalid_argument("fit_collapse: no positive increment");
  const LogLawFit f = solve(P, sigma);
  CollapseFit c;
  c.c1 = f.C;
  c.sigma_c1 = f.sigma_C;
  c.c2 = 1.0 / f.n0;
  c.sigma_c2 = f.sigma_n0 / (f.n0 * f.n0);
  c.corr = -f.corr;  // c2 falls as n0 rises
  c.chi2 = f.rss;
  c.dof = f.dof;
  c.chi2_red = f.chi2_red;
  c.weighted = f.weighted;
  c.converged = f.converged;
  c.at_bound = f.at_bound;
  c.points = static_cast<int>(N);
  return c;
}

}  // namespace crumple::analysis
