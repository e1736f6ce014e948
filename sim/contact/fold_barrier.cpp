// Fold barrier (fold_barrier.hpp).
#include "sim/contact/fold_barrier.hpp"

#include "sim/model/barrier_function.hpp"
#include "sim/model/hinge_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {

namespace {

double opening(double theta) { return M_PI - std::abs(theta); }

}  // namespace

FoldBarrierTerm::FoldBarrierTerm(const Mesh& mesh, double ks, double sigma)
    : mesh_(&mesh), K_(ks * sigma * sigma) {
  psi0_.resize(mesh.num_hinges());
  for (Index h = 0; h < mesh.num_hinges(); ++h) {
    const auto& nd = mesh.hinges[h].nodes;
    const Vec3 x0 = mesh.ref.col(nd[0]), e = mesh.ref.col(nd[1]) - x0;
    const double len = e.norm();
    const double w2 = e.cross(Vec3(mesh.ref.col(nd[2]) - x0)).norm() / len;
    const double w3 = e.cross(Vec3(mesh.ref.col(nd[3]) - x0)).norm() / len;
    psi0_[h] = std::min(sigma / std::min(w2, w3), 0.5 * M_PI);
  }
  // The prefilter's bound, a hair below cos(psi0) so that rounding cannot drop a hinge the
  // exact test keeps.
  cos_onset_sq_.resize(psi0_.size());
  for (std::size_t h = 0; h < psi0_.size(); ++h) {
    const double c = std::max(0.0, std::cos(psi0_[h]) - 1e-9);
    cos_onset_sq_[h] = c * c;
  }
}

std::vector<Index> FoldBarrierTerm::active_hinges(const VecX& x) const {
  std::vector<Index> out;
  for (const auto& [h, theta] : near_complete_folds(x)) out.push_back(h);
  return out;
}

std::vector<std::pair<Index, double>> FoldBarrierTerm::near_complete_folds(const VecX& x) const {
  // psi < psi0 means cos(theta) = n1.n2 < -cos(psi0). With the unnormalised normals a, b that
  // is a.b < 0 and (a.b)^2 > cos^2(psi0) |a|^2 |b|^2: no square root, division or atan2 for the
  // hinges that are far from a fold, which are nearly all of them. The few that pass get their
  // bend angle and the exact test.
  const Index nh = mesh_->num_hinges();
  std::vector<char> near(nh);
#pragma omp parallel for schedule(static)
  for (Index h = 0; h < nh; ++h) {
    const auto& nd = mesh_->hinges[h].nodes;
    const Vec3 x0 = node(x, nd[0]), e0 = node(x, nd[1]) - x0;
    const Vec3 a = e0.cross(node(x, nd[2]) - x0), b = (node(x, nd[3]) - x0).cross(e0);
    const double ab = a.dot(b);
    near[h] = ab < 0 && ab * ab > cos_onset_sq_[h] * a.squaredNorm() * b.squaredNorm();
  }
  std::vector<std::pair<Index, double>> out;
  for (Index h = 0; h < nh; ++h) {
    if (!near[h]) continue;
    const auto& nd = mesh_->hinges[h].nodes;
    const double theta = bend_angle(node(x, nd[0]), node(x, nd[1]), node(x, nd[2]), node(x, nd[3]));
    if (opening(theta) < psi0_[h]) out.emplace_back(h, theta);
  }
  return out;
}

double FoldBarrierTerm::energy(const State& s) const {
  double e = 0;
  for (const auto& [h, theta] : near_complete_folds(s.x))
    e += cubic_barrier(K_, psi0_[h], opening(theta)).e;
  return e;
}

void FoldBarrierTerm::add_force(const State& s, VecX& f) const {
  // Few hinges are ever near a complete fold: a serial pass over them, in hinge order.
  for (Index h : active_hinges(s.x)) {
    const auto& nd = mesh_->hinges[h].nodes;
    Vec12 g;
    const double th = bend_angle_derivatives(node(s.x, nd[0]), node(s.x, nd[1]),
                                             node(s.x, nd[2]), node(s.x, nd[3]), g, nullptr);
    const BarrierValue b = cubic_barrier(K_, psi0_[h], opening(th));
    // F = -E' grad psi = E' sign(theta) grad theta
    const double w = b.d1 * (th >= 0 ? 1.0 : -1.0);
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * nd[a]) += w * g.segment<3>(3 * a);
  }
}

void FoldBarrierTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
  for (Index h : active_hinges(s.x)) {
    const auto& nd = mesh_->hinges[h].nodes;
    Vec12 g;
    Mat12 H;
    const double th = bend_angle_derivatives(node(s.x, nd[0]), node(s.x, nd[1]),
                                             node(s.x, nd[2]), node(s.x, nd[3]), g, &H);
    const BarrierValue b = cubic_barrier(K_, psi0_[h], opening(th));
    const double sg = th >= 0 ? 1.0 : -1.0;
    Mat12 K = b.d2 * g * g.transpose() - (b.d1 * sg) * H;
    const auto& sl = slots_[h];
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) add_block(val, sl[4 * a + c], K.block<3, 3>(3 * a, 3 * c));
  }
}

void FoldBarrierTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  for (const auto& hg : mesh_->hinges)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) out.emplace_back(hg.nodes[a], hg.nodes[b]);
}

void FoldBarrierTerm::bind(const BlockPattern& pattern) {
  slots_.resize(mesh_->num_hinges());
  for (Index h = 0; h < mesh_->num_hinges(); ++h) {
    const auto& nd = mesh_->hinges[h].nodes;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) slots_[h][4 * a + b] = pattern.slot(nd[a], nd[b]);
  }
}

}  // namespace crumple
