// One attempt of the explicit RK4(3) step over (x, v, p) (integrator.hpp; paper §3.4):
// x' = v, v' = F / m, p' = g(c(x), p).
#include "sim/core/parallel_assign.hpp"
#include "sim/integrate/error_norm.hpp"
#include "sim/integrate/integrator.hpp"
#include "sim/integrate/rk43.hpp"

#include <omp.h>

#include <algorithm>
#include <string>

namespace crumple {

double Integrator::plastic_rate_at(const VecX& x, const VecX& p, VecX& g) const {
  VecX c;
  if (law_.enabled) model_.bending().curvatures(x, c);
  return plastic_rate_from(c, p, g);
}

double Integrator::plastic_rate_from(const VecX& c, const VecX& p, VecX& g) const {
  g.setZero(p.size());
  if (!law_.enabled) return 0.0;
  double gmax = 0;
#pragma omp parallel for schedule(static) reduction(max : gmax)
  for (Index h = 0; h < static_cast<Index>(p.size()); ++h) {
    g[h] = law_.g(c[h], p[h]);
    gmax = std::max(gmax, std::abs(g[h]));
  }
  return gmax;
}

void Integrator::explicit_rhs(double t, const VecX& y, VecX& dy, State& sc) {
  const Index n3 = model_.num_dofs(), nh = model_.num_hinges();
  const double t0 = omp_get_wtime();
  sc.t = t;
  parallel_assign(sc.x, y.head(n3));
  parallel_assign(sc.v, y.segment(n3, n3));
  parallel_assign(sc.p, y.tail(nh));
  VecX F, g;
  model_.forces(sc, F);
  // The curvatures of sc, kept by the bending force just evaluated (unread without plasticity).
  plastic_rate_from(model_.bending().last_curvatures(), sc.p, g);
  dy.resize(y.size());
  auto dx = dy.head(n3), dv = dy.segment(n3, n3), dp = dy.tail(nh);
  parallel_assign(dx, sc.v);
  parallel_assign(dv, F / model_.params().mass);
  parallel_assign(dp, g);
  hist_.counters.wall_assembly += omp_get_wtime() - t0;
}

void Integrator::explicit_attempt(const State& s, double h, Attempt& a) {
  const Index n3 = model_.num_dofs(), nh = model_.num_hinges();
  a.order = 4;
  VecX y(2 * n3 + nh);
  auto yx = y.head(n3), yv = y.segment(n3, n3), yp = y.tail(nh);
  parallel_assign(yx, s.x);
  parallel_assign(yv, s.v);
  parallel_assign(yp, s.p);
  State scratch;
  auto f = [&](double t, const VecX& yy, VecX& dy) { explicit_rhs(t, yy, dy, scratch); };
  // k1 is the previous step's last stage when there is one (read in place, not copied).
  const bool fsal = hist_.fsal.size() == y.size();
  VecX k1_fresh;
  if (!fsal) f(s.t, y, k1_fresh);
  const VecX& k1 = fsal ? hist_.fsal : k1_fresh;
  VecX y4, y3, k5;
  rk43_step(f, s.t, y, h, k1, y4, y3, k5);

  // Worst node by acceleration at the end of the step (also the switching criterion).
  double amax = -1;
  for (Index i = 0; i < n3 / 3; ++i) {
    const double ai = k5.segment<3>(n3 + 3 * i).norm();
    if (!(ai <= amax)) {
      amax = ai;
      a.worst_node = i;
    }
    if (std::isnan(ai)) break;
  }
  if (!y4.allFinite() || !k5.allFinite()) {
    a.failure = "non-finite state in the explicit step";
    // Name the terms whose force is not finite at the step's start (if any): the diagnostic
    // a failed run prints.
    std::string bad;
    for (const auto& [name, f] : forces_by_term(s))
      if (!f.allFinite()) bad += (bad.empty() ? "" : ", ") + name;
    if (!bad.empty()) a.failure += " (non-finite force at the start from: " + bad + ")";
    return;
  }
  a.ok = true;
  // Over (x, v, p); without plasticity p is a constant and its zero errors are left out.
  const Index ne = law_.enabled ? y.size() : 2 * n3;
  a.err = std::sqrt(weighted_sq_sum(y4.head(ne) - y3.head(ne), y4.head(ne), settings_.atol,
                                    settings_.explicit_rtol) /
                    static_cast<double>(ne));
  a.a_ratio = amax / a_ref_;
  a.next.t = s.t + h;
  parallel_assign(a.next.x, y4.head(n3));
  parallel_assign(a.next.v, y4.segment(n3, n3));
  parallel_assign(a.next.p, y4.tail(nh));
  a.fsal = std::move(k5);
}

}  // namespace crumple
