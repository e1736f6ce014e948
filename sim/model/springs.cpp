// In-plane springs (springs.hpp, paper eq. 3 and B.1-B.3).
#include "sim/model/springs.hpp"

#include "sim/model/edge_colors.hpp"

namespace crumple {

SpringTerm::SpringTerm(const Mesh& mesh, double ks)
    : mesh_(&mesh), ks_(ks), colors_(color_edges(mesh)) {}

double SpringTerm::energy(const State& s) const {
  double e = 0.0;
  const Index m = mesh_->num_edges();
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (Index k = 0; k < m; ++k) {
    const auto [i, j] = mesh_->edges[k];
    const double d = (node(s.x, i) - node(s.x, j)).norm() - mesh_->rest_length[k];
    e += 0.5 * ks_ * d * d;
  }
  return e;
}

void SpringTerm::add_force(const State& s, VecX& f) const {
  for_each_colored(colors_, [&](Index k) {
    const auto [i, j] = mesh_->edges[k];
    const Vec3 r = node(s.x, i) - node(s.x, j);
    const Vec3 fi = ks_ * (mesh_->rest_length[k] / r.norm() - 1.0) * r;
    f.segment<3>(3 * i) += fi;
    f.segment<3>(3 * j) -= fi;
  });
}

void SpringTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
  for_each_colored(colors_, [&](Index k) {
    const auto [i, j] = mesh_->edges[k];
    const Mat3 K = ks_ * spring_block(node(s.x, i) - node(s.x, j), mesh_->rest_length[k]);
    const auto& sl = slots_[k];
    add_block(val, sl[0], K);
    add_block(val, sl[1], -K);
    add_block(val, sl[2], -K);
    add_block(val, sl[3], K);
  });
}

void SpringTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  for (const auto& e : mesh_->edges) out.emplace_back(e[0], e[1]);
}

void SpringTerm::bind(const BlockPattern& p) {
  slots_.resize(mesh_->num_edges());
  for (Index k = 0; k < mesh_->num_edges(); ++k)
    slots_[k] = pair_slots(p, mesh_->edges[k][0], mesh_->edges[k][1]);
}

}  // namespace crumple
