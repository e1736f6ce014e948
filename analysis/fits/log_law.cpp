// Levenberg-Marquardt fit of l = C ln(1 + n/n0) and of its increments; see log_law.hpp.
//
// Both fits share one problem: y_i = C [ln(1 + n_i/n0) - ln(1 + m_i/n0)], with m_i = 0 for the
// cumulative law and m_i = the previous cycle for the increments. The iteration runs on
// (C, u = ln n0) so n0 stays positive without constraints; the reported covariance is computed
// afterwards from the Jacobian in (C, n0), which at the optimum is the same first-order result
// as transforming the (C, u) covariance.
#include "analysis/fits/log_law.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace crumple::analysis {
namespace {

struct Problem {
  Eigen::ArrayXd m, n, l, w;  // from, to, data, w = 1/sigma

  Eigen::ArrayXd basis(double n0) const { return (1.0 + n / n0).log() - (1.0 + m / n0).log(); }
  Eigen::ArrayXd model(double C, double n0) const { return C * basis(n0); }
  double rss(double C, double n0) const { return ((model(C, n0) - l) * w).square().sum(); }

  /// Weighted Jacobian of the model with respect to (C, n0).
  Eigen::MatrixX2d jacobian(double C, double n0) const {
    Eigen::MatrixX2d J(n.size(), 2);
    J.col(0) = (basis(n0) * w).matrix();
    J.col(1) = (-C * (n / (n0 * (n0 + n)) - m / (n0 * (n0 + m))) * w).matrix();
    return J;
  }

  /// Best C for fixed n0: the model is linear in C.
  double best_C(double n0) const {
    const Eigen::ArrayXd g = basis(n0) * w;
    return (g * l * w).sum() / g.square().sum();
  }
};

LogLawFit solve(Problem& P, const std::vector<double>& sigma) {
  const Eigen::Index N = P.n.size();
  if (!sigma.empty()) {
    P.w = 1.0 / Eigen::Map<const Eigen::ArrayXd>(sigma.data(), N);
    if (!(P.w.isFinite().all() && (P.w > 0).all()))
      throw std::invalid_argument("fit_log_law: sigmas must be positive");
  }
  // Start from the best point of a log-spaced scan of n0 (C eliminated exactly), so LM begins
  // in the right basin even when the data barely bend.
  double u = 0.0, best = INFINITY;
  for (int i = 0; i <= 140; ++i) {
    const double ui = std::log(1e-3) + i * (std::log(1e4) - std::log(1e-3)) / 140.0;
    const double r = P.rss(P.best_C(std::exp(ui)), std::exp(ui));
    if (r < best) best = r, u = ui;
  }
  double C = P.best_C(std::exp(u)), lambda = 1e-3, cur = P.rss(C, std::exp(u));
  LogLawFit fit;
  for (fit.iterations = 0; fit.iterations < 500; ++fit.iterations) {
    const double n0 = std::exp(u);
    Eigen::MatrixX2d J = P.jacobian(C, n0);
    J.col(1) *= n0;  // d/du = n0 d/dn0
    const Eigen::VectorXd r = ((P.model(C, n0) - P.l) * P.w).matrix();
    const Eigen::Matrix2d A = J.transpose() * J;
    const Eigen::Vector2d g = J.transpose() * r;
    bool accepted = false;
    while (lambda < 1e12) {
      Eigen::Matrix2d M = A;
      M.diagonal() += lambda * A.diagonal();
      const Eigen::Vector2d step = M.ldlt().solve(-g);
      const double trial = P.rss(C + step(0), std::exp(u + step(1)));
      if (std::isfinite(trial) && trial <= cur) {
        const double drop = cur - trial;
        C += step(0), u += step(1), cur = trial;
        lambda = std::max(lambda / 10.0, 1e-12);
        accepted = true;
        if (drop <= 1e-14 * (cur + 1e-300) || step.norm() < 1e-12) fit.converged = true;
        break;
      }
      lambda *= 10.0;
    }
    if (!accepted) fit.converged = true;  // no downhill step left: at a minimum
    if (fit.converged) break;
  }

  fit.C = C;
  fit.n0 = std::exp(u);
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
            Eigen::Map<const Eigen::ArrayXd>(l.data(), N), Eigen::ArrayXd::Ones(N)};
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
            Eigen::Map<const Eigen::ArrayXd>(dl.data(), N), Eigen::ArrayXd::Ones(N)};
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

}  // namespace crumple::analysis
