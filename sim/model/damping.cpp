// Isotropic drag and internal damping (damping.hpp, paper eq. 8-9 and B.5-B.7).
#include "sim/model/damping.hpp"

#include "sim/model/edge_colors.hpp"
#include "sim/model/springs.hpp"

namespace crumple {

DragTerm::DragTerm(Index num_nodes, double b_iso) : n_(num_nodes), b_(b_iso) {}

void DragTerm::add_force(const State& s, VecX& f) const { f.noalias() -= b_ * s.v; }

void DragTerm::add_jacobians(const State&, Jacobians& J) const {
  double* val = J.Hv.valuePtr();
  const Mat3 B = b_ * Mat3::Identity();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n_; ++i) add_block(val, slots_[i], B);
}

void DragTerm::bind(const BlockPattern& p) {
  slots_.resize(n_);
  for (Index i = 0; i < n_; ++i) slots_[i] = p.slot(i, i);
}

InternalDampingTerm::InternalDampingTerm(const Mesh& mesh, double b_int)
    : mesh_(&mesh), b_(b_int), colors_(color_edges(mesh)) {}

void InternalDampingTerm::add_force(const State& s, VecX& f) const {
  for_each_colored(colors_, [&](Index k) {
    const auto [i, j] = mesh_->edges[k];
    const Vec3 r = node(s.x, i) - node(s.x, j);
    const Vec3 u = node(s.v, i) - node(s.v, j);
    // Building the 3x3 block only to multiply one vector took most of this loop (profile of
    // explicit steps, 12000 nodes).
    const Vec3 fi = -b_ * spring_block_times(r, mesh_->rest_length[k], u);
    f.segment<3>(3 * i) += fi;
    f.segment<3>(3 * j) -= fi;
  });
}

void InternalDampingTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* hx = J.Hx.valuePtr();
  double* hv = J.Hv.valuePtr();
  for_each_colored(colors_, [&](Index k) {
    const auto [i, j] = mesh_->edges[k];
    const double sl = mesh_->rest_length[k];
    const Vec3 r = node(s.x, i) - node(s.x, j);
    const Vec3 u = node(s.v, i) - node(s.v, j);
    const double l2 = r.squaredNorm(), l = std::sqrt(l2);
    const double ru = r.dot(u);
    const Mat3 Kv = b_ * spring_block(r, sl);
    const Mat3 Kx = (b_ * sl / (l2 * l)) * (u * r.transpose() + r * u.transpose() +
                                           ru * Mat3::Identity() - (3.0 * ru / l2) * r * r.transpose());
    const auto& st = slots_[k];
    add_block(hv, st[0], Kv);
    add_block(hv, st[1], -Kv);
    add_block(hv, st[2], -Kv);
    add_block(hv, st[3], Kv);
    add_block(hx, st[0], Kx);
    add_block(hx, st[1], -Kx);
    add_block(hx, st[2], -Kx);
    add_block(hx, st[3], Kx);
  });
}

void InternalDampingTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  for (const auto& e : mesh_->edges) out.emplace_back(e[0], e[1]);
}

void InternalDampingTerm::bind(const BlockPattern& p) {
  slots_.resize(mesh_->num_edges());
  for (Index k = 0; k < mesh_->num_edges(); ++k)
    slots_[k] = pair_slots(p, mesh_->edges[k][0], mesh_->edges[k][1]);
}

}  // namespace crumple
