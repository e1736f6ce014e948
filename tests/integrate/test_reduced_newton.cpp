// The reduced Newton solve (eq. 35) equals a dense solve of the full 3 x 3 block system (34),
// on a tiny folded sheet with hinges outside the plastic dead band.
#include "sim/integrate/linear_solver.hpp"
#include "sim/integrate/reduced_newton.hpp"
#include "tests/support/grid_mesh.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <random>

using namespace crumple;

namespace {

ModelParams tiny_params() {
  ModelParams mp;
  mp.ks = 50;
  mp.kb = 0.3;
  mp.b_iso = 0.7;
  mp.b_int = 0.2;
  return mp;
}

// A folded, moving iterate: fold about the line x = 0.5 plus noise, random v and p.
State folded_iterate(const SheetModel& model) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> N(0, 1);
  State s = model.rest_state();
  for (Index i = 0; i < model.num_nodes(); ++i) {
    const double u = s.x[3 * i] - 0.5;
    s.x[3 * i + 2] = 0.8 * std::abs(u) + 0.02 * N(rng);
    s.x[3 * i] += 0.01 * N(rng);
  }
  for (Index k = 0; k < s.v.size(); ++k) s.v[k] = 0.1 * N(rng);
  for (Index k = 0; k < s.p.size(); ++k) s.p[k] = 0.2 * N(rng);
  s.t = 0.3;
  return s;
}

// A spring between two nodes that no element joins: a new node pair in the pattern.
class TieTerm : public ForceTerm {
 public:
  TieTerm(Index i, Index j, double k) : i_(i), j_(j), k_(k) {}
  std::string name() const override { return "tie"; }
  double energy(const State& s) const override {
    return 0.5 * k_ * (node(s.x, i_) - node(s.x, j_)).squaredNorm();
  }
  void add_force(const State& s, VecX& f) const override {
    const Vec3 d = k_ * (node(s.x, i_) - node(s.x, j_));
    f.segment<3>(3 * i_) -= d;
    f.segment<3>(3 * j_) += d;
  }
  void add_jacobians(const State&, Jacobians& J) const override {
    const Mat3 K = k_ * Mat3::Identity();
    add_block(J.Hx.valuePtr(), slots_[0], K);
    add_block(J.Hx.valuePtr(), slots_[1], -K);
    add_block(J.Hx.valuePtr(), slots_[2], -K);
    add_block(J.Hx.valuePtr(), slots_[3], K);
  }
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override {
    out.emplace_back(i_, j_);
  }
  void bind(const BlockPattern& p) override {
    slots_ = {p.slot(i_, i_), p.slot(i_, j_), p.slot(j_, i_), p.slot(j_, j_)};
  }

 private:
  Index i_, j_;
  double k_;
  std::array<BlockSlot, 4> slots_;
};

// A 4 x 4 sheet, its plastic law and the folded iterate both tests linearise at.
struct FoldedSheet {
  Mesh mesh = crumple::testing::grid_mesh(4, 4, 1.0, 1.0, 0.15, 7);
  SheetModel model{mesh, tiny_params()};
  PlasticLaw law{0.05, 0.3, 2.0, true};
  State s = folded_iterate(model);
};

// Hinges outside the plastic dead band (their rank-1 blocks enter the matrix).
int plastic_hinges(const ReducedNewton& rn) {
  int active = 0;
  for (Index h = 0; h < rn.dg_dc().size(); ++h) active += rn.dg_dc()[h] > 0;
  return active;
}

}  // namespace

TEST(ReducedNewton, EqualsDenseFullSystemSolve) {
  FoldedSheet f;
  const Mesh& mesh = f.mesh;
  SheetModel& model = f.model;
  const State& s = f.s;
  ReducedNewton rn(model, f.law);
  const double bh = 0.05;
  VecX hx = -s.x + 0.01 * VecX::Random(s.x.size());  // history sums (arbitrary but fixed)
  VecX hp = -s.p + 0.01 * VecX::Random(s.p.size());

  rn.linearise(s, bh, hx, hp);
  ASSERT_GT(plastic_hinges(rn), 3) << "the test needs hinges outside the dead band";

  LinearSolver direct(LinearSolverKind::DirectLDLT, 18, 1e-12, 100);
  VecX dx, dv, dp;
  ASSERT_TRUE(direct.solve(rn.matrix(), rn.rhs(), dx).ok);
  rn.recover(dx, dv, dp);

  // Dense full system with the model's own Hp (not the rank-1 formula used by the reduction).
  Jacobians J;
  model.jacobians(s, J, true);
  const Index n3 = model.num_dofs(), nh = model.num_hinges();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n3 + nh, 2 * n3 + nh);
  K.block(0, 0, n3, n3).setIdentity();
  K.block(0, n3, n3, n3) = -bh * Eigen::MatrixXd::Identity(n3, n3);
  for (Index h = 0; h < nh; ++h) {
    const auto& nd = mesh.hinges[h].nodes;
    for (int a = 0; a < 4; ++a)  // bh Gx, Gx = -dg/dx = -g' grad c
      K.block(2 * n3 + h, 3 * nd[a], 1, 3) =
          -bh * rn.dg_dc()[h] * rn.curvature_gradient()[h].segment<3>(3 * a).transpose();
    K(2 * n3 + h, 2 * n3 + h) = 1.0 + bh * rn.dg_dc()[h];  // I + bh Gp, Gp = -dg/dp = g'
  }
  // Row order of (34) is (x, p, alg); columns (x, v, p). Put alg rows at n3..2n3.
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n3 + nh, 2 * n3 + nh);
  M.topRows(n3) = K.topRows(n3);
  M.block(n3, 0, n3, n3) = Eigen::MatrixXd(J.Hx);
  M.block(n3, n3, n3, n3) = Eigen::MatrixXd(J.Hv);
  M.block(n3, 2 * n3, n3, nh) = Eigen::MatrixXd(J.Hp);
  M.bottomRows(nh) = K.bottomRows(nh);
  VecX r(2 * n3 + nh);
  r << rn.r_x(), -rn.force(), rn.r_p();
  const VecX full = M.fullPivLu().solve(-r);

  const double scale = full.norm();
  EXPECT_LT((full.head(n3) - dx).norm() / scale, 1e-9);
  EXPECT_LT((full.segment(n3, n3) - dv).norm() / scale, 1e-9);
  EXPECT_LT((full.tail(nh) - dp).norm() / scale, 1e-9);
  EXPECT_GT(dp.norm(), 1e-6);  // plastic unknowns really moved
}

// A pattern rebuilt by someone other than the integrator (the protocol runner does at a stage
// begin, after a stage added terms or switched contact) moves every block's slot: the next
// linearisation must follow it, or the plastic blocks land in the wrong places.
TEST(ReducedNewton, FollowsAPatternRebuiltElsewhere) {
  FoldedSheet f;
  ReducedNewton rn(f.model, f.law);
  const VecX hx = -f.s.x, hp = -f.s.p;
  rn.linearise(f.s, 0.05, hx, hp);

  f.model.add_term(std::make_shared<TieTerm>(0, f.model.num_nodes() - 1, 3.0),
                   TermKind::External);
  ASSERT_TRUE(f.model.rebuild_pattern());
  rn.linearise(f.s, 0.05, hx, hp);
  ReducedNewton fresh(f.model, f.law);
  fresh.linearise(f.s, 0.05, hx, hp);
  ASSERT_GT(plastic_hinges(fresh), 3) << "the test needs plastic blocks";
  const SpMat diff = rn.matrix() - fresh.matrix();
  EXPECT_LT(diff.norm(), 1e-14 * fresh.matrix().norm());
}
