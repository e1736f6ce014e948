// One attempt of the quasistatic BDF step with plasticity (integrator.hpp; paper eq. 31-35).
#include "sim/integrate/bdf.hpp"
#include "sim/integrate/error_norm.hpp"
#include "sim/integrate/forcing.hpp"
#include "sim/integrate/integrator.hpp"

#include <omp.h>

#include <algorithm>

namespace crumple {

namespace {

/// The node with the largest residual force |F_i| (a NaN wins: it is where the failure is).
Index largest_force_node(const VecX& F) {
  Index worst = -1;
  double fmax = -1;
  for (Index i = 0; i < static_cast<Index>(F.size() / 3); ++i) {
    const double fi = F.segment<3>(3 * i).norm();
    if (!(fi <= fmax)) {  // also picks up NaN
      fmax = fi;
      worst = i;
    }
    if (std::isnan(fi)) break;
  }
  return worst;
}

}  // namespace

double Integrator::implicit_predict(const State& s, double h, int ord, std::vector<double> tc,
                                    State& it) {
  const IntegratorHistory& H = hist_;
  it.t = s.t + h;
  if (H.times.size() >= 2) {
    const std::vector<double> nodes(H.times.begin(), H.times.begin() + ord + 1);
    const auto w = lagrange_weights(nodes, it.t);
    it.x = w[0] * H.xs[0];
    it.v = w[0] * H.vs[0];
    it.p = w[0] * H.ps[0];
    for (int j = 1; j <= ord; ++j) {
      it.x += w[j] * H.xs[j];
      it.v += w[j] * H.vs[j];
      it.p += w[j] * H.ps[j];
    }
    tc.push_back(H.times[ord]);
    return bdf_error_factor(tc);
  }
  // First step after a (re)start: Taylor predictor. For BDF1 the corrector error is
  // -h^2 x''/2 and corrector - predictor is h^2 x'', hence the factor -1/2.
  VecX g;
  plastic_rate_at(s.x, s.p, g);
  it.x = s.x + h * s.v;
  it.v = s.v;
  it.p = s.p + h * g;
  return -0.5;
}

bool Integrator::implicit_newton(double bh, const VecX& hx, const VecX& hp, Attempt& a) {
  State& it = a.next;
  VecX dx, dv, dp;
  double prev_norm = 0;
  const ForcingTerms forcing{settings_.cg_tol, settings_.cg_tol_max, settings_.newton_tol};
  for (int k = 1; k <= settings_.newton_max_iters; ++k) {
    a.newton_iters = k;
    double t0 = omp_get_wtime();
    newton_->linearise(it, bh, hx, hp);
    hist_.counters.wall_assembly += omp_get_wtime() - t0;
    ++hist_.counters.newton_iters;
    a.worst_node = largest_force_node(newton_->force());
    if (!newton_->rhs().allFinite()) {
      a.failure = "non-finite force or residual";
      return false;
    }
    const double eta = forcing.at(k, prev_norm);
    t0 = omp_get_wtime();
    const LinearSolveResult ls = solver_.solve(newton_->matrix(), newton_->rhs(), dx, eta, &it.x);
    hist_.counters.wall_linear += omp_get_wtime() - t0;
    a.cg_iters += ls.iterations;
    hist_.counters.cg_iters += ls.iterations;
    if (!ls.ok) {
      a.not_spd = ls.not_spd;
      a.newton_failed = !ls.not_spd;
      a.failure = ls.failure;
      return false;
    }
    newton_->recover(dx, dv, dp);
    it.x += dx;
    it.v += dv;
    if (law_.enabled) it.p += dp;
    const double norm = wrms2(dx, it.x, law_.enabled ? dp : VecX(), it.p, settings_.atol,
                              settings_.rtol);
    if (!std::isfinite(norm) || !it.v.allFinite()) {
      a.failure = "non-finite Newton update";
      return false;
    }
    if (norm <= settings_.newton_tol) return true;
    if (k >= 3 && norm > prev_norm) {  // not contracting: give up early, retry with smaller h
      a.newton_failed = true;
      a.failure = "Newton diverging";
      return false;
    }
    prev_norm = norm;
  }
  a.newton_failed = true;
  a.failure = "Newton did not converge in " + std::to_string(settings_.newton_max_iters) +
              " iterations";
  return false;
}

double Integrator::realised_acceleration_ratio(const State& s, const State& it, double h) const {
  // The force is evaluated at the converged iterate: the Newton object holds the force before
  // the last correction, which after a single iteration is the predictor's residual and would
  // overstate a_max by orders.
  VecX F;
  model_.forces(it, F);
  const double m = model_.params().mass;
  double amax = 0;
  for (Index i = 0; i < static_cast<Index>(F.size() / 3); ++i) {
    const double af = F.segment<3>(3 * i).norm() / m;
    const double av = (it.v.segment<3>(3 * i) - s.v.segment<3>(3 * i)).norm() / h;
    amax = std::max({amax, af, av});
  }
  return amax / a_ref_;
}

// The BDF step of order ord (climbing to bdf_order as history accumulates): coefficients on
// the step's time points, the predictor, Newton on the reduced system, then the local error
// from corrector minus predictor (Milne's device) and the switching measure.
void Integrator::implicit_attempt(const State& s, double h, Attempt& a) {
  const IntegratorHistory& H = hist_;
  const int npts = static_cast<int>(H.times.size());
  const int ord = npts >= 2 ? std::min(settings_.bdf_order, npts - 1) : 1;
  a.order = ord;

  std::vector<double> tc{s.t + h};
  for (int j = 0; j < ord; ++j) tc.push_back(H.times[j]);
  const BdfCoefficients co = bdf_coefficients(tc);
  const double bh = co.beta * co.h;
  VecX hx = VecX::Zero(s.x.size()), hp = VecX::Zero(s.p.size());
  for (int j = 0; j < ord; ++j) {
    hx += co.alpha[j] * H.xs[j];
    hp += co.alpha[j] * H.ps[j];
  }

  // Predictor and the factor turning (corrector - predictor) into the local error.
  State& it = a.next;
  const double E = implicit_predict(s, h, ord, tc, it);
  const VecX x_pred = it.x, p_pred = it.p;
  if (!implicit_newton(bh, hx, hp, a)) return;
  a.ok = true;
  // Without plasticity p is a constant, not an unknown: counting its zero errors would dilute
  // the RMS (by about sqrt(2) on a sheet, as many hinges as coordinates).
  a.err = std::abs(E) * wrms2(it.x - x_pred, it.x, law_.enabled ? VecX(it.p - p_pred) : VecX(),
                              it.p, settings_.atol, settings_.rtol);
  // Residual and realised acceleration (switching criterion, §3.4).
  a.a_ratio = realised_acceleration_ratio(s, it, h);
}

}  // namespace crumple
