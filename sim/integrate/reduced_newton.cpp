// The reduced Newton system of the quasistatic BDF step (reduced_newton.hpp; eq. 35).
#include "sim/integrate/reduced_newton.hpp"

#include "sim/model/edge_colors.hpp"

#include <stdexcept>

namespace crumple {

ReducedNewton::ReducedNewton(const SheetModel& model, const PlasticLaw& law)
    : model_(model), law_(law), hinge_colors_(color_hinges(model.mesh())) {
  bind();
}

void ReducedNewton::bind() {
  const Mesh& m = model_.mesh();
  const BlockPattern& pat = model_.pattern();
  bound_serial_ = model_.pattern_serial();
  slots_.resize(m.num_hinges());
  for (Index h = 0; h < m.num_hinges(); ++h) {
    const auto& nd = m.hinges[h].nodes;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) slots_[h][4 * a + b] = pat.slot(nd[a], nd[b]);
  }
}

void ReducedNewton::linearise(const State& s, double bh, const VecX& hx, const VecX& hp) {
  const Mesh& m = model_.mesh();
  const Index nh = m.num_hinges();
  if (bound_serial_ != model_.pattern_serial()) bind();
  bh_ = bh;
  model_.forces(s, F_);
  model_.jacobians(s, J_, false);
  model_.bending().curvature_gradients(s.x, c_, grad_);

  rx_ = s.x + hx - bh * s.v;
  rp_.resize(nh);
  dg_.resize(nh);
  D_.resize(nh);
  for (Index h = 0; h < nh; ++h) {
    rp_[h] = s.p[h] + hp[h] - bh * law_.g(c_[h], s.p[h]);
    dg_[h] = law_.dg_dc(c_[h], s.p[h]);
    D_[h] = 1.0 / (1.0 + bh * dg_[h]);  // Gp_h = -dg/dp = g'_h
  }

  // A = Hx + Hv / bh: both matrices are copies of the pattern, so their values align.
  if (J_.Hx.nonZeros() != J_.Hv.nonZeros())
    throw std::logic_error("ReducedNewton: Hx and Hv are not on the same pattern");
  A_ = J_.Hx;
  {
    double* a = A_.valuePtr();
    const double* hv = J_.Hv.valuePtr();
    const Eigen::Index nnz = A_.nonZeros();
    const double inv = 1.0 / bh;
#pragma omp parallel for schedule(static)
    for (Eigen::Index k = 0; k < nnz; ++k) a[k] += inv * hv[k];
  }

  // b = F - Hv r_x / bh + Hp D r_p, with Hp D r_p = -sum_h kb f_h D_h r_p,h grad c_h.
  b_ = F_ - (J_.Hv * rx_) / bh;
  const double kb = model_.bending().kb();
  double* val = A_.valuePtr();
  for_each_colored(hinge_colors_, [&](Index h) {
    const auto& hg = m.hinges[h];
    const double kf = kb * hg.rest_factor;
    const Vec12& gc = grad_[h];
    const double wb = -kf * D_[h] * rp_[h];
    if (wb != 0.0)
      for (int a = 0; a < 4; ++a) b_.segment<3>(3 * hg.nodes[a]) += wb * gc.segment<3>(3 * a);
    const double w = bh * kf * D_[h] * dg_[h];
    if (w == 0.0) return;
    const auto& sl = slots_[h];
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c)
        add_block(val, sl[4 * a + c], -w * gc.segment<3>(3 * a) * gc.segment<3>(3 * c).transpose());
  });
}

void ReducedNewton::recover(const VecX& dx, VecX& dv, VecX& dp) const {
  const Mesh& m = model_.mesh();
  const Index nh = m.num_hinges();
  dv = (rx_ + dx) / bh_;
  dp.resize(nh);
  for (Index h = 0; h < nh; ++h) {
    const auto& nd = m.hinges[h].nodes;
    double gdx = 0.0;  // grad c_h . dx on the stencil
    for (int a = 0; a < 4; ++a) gdx += grad_[h].segment<3>(3 * a).dot(dx.segment<3>(3 * nd[a]));
    // Gx dx = -g'_h grad c . dx
    dp[h] = -D_[h] * (rp_[h] - bh_ * dg_[h] * gdx);
  }
}

}  // namespace crumple
