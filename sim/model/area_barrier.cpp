// Area barrier (area_barrier.hpp).
#include "sim/model/area_barrier.hpp"

#include "sim/model/barrier_function.hpp"

#include <cmath>
#include <stdexcept>

namespace crumple {

namespace {

Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

// n and the opposite-edge vectors d_i = x_{i+2} - x_{i+1} of triangle t at x.
struct TriangleGeometry {
  Vec3 n;
  std::array<Vec3, 3> d;
};

TriangleGeometry geometry(const Mesh& m, const VecX& x, Index t) {
  const auto& tr = m.triangles[t];
  const Vec3 x0 = node(x, tr[0]), x1 = node(x, tr[1]), x2 = node(x, tr[2]);
  return {(x1 - x0).cross(x2 - x0), {x2 - x1, x0 - x2, x1 - x0}};
}

}  // namespace

AreaBarrierTerm::AreaBarrierTerm(const Mesh& mesh, double ks, double onset)
    : mesh_(&mesh), q0_(onset * onset) {
  if (!(onset > 0 && onset < 1))
    throw std::invalid_argument("AreaBarrierTerm: the onset must be an area ratio in (0, 1)");
  const Index nt = mesh.num_triangles();
  n0_sq_.resize(nt);
  K_.resize(nt);
  limit_.resize(nt);
  const VecX ref = mesh.ref_flat();
  for (Index t = 0; t < nt; ++t) {
    const auto g = geometry(mesh, ref, t);
    n0_sq_[t] = g.n.squaredNorm();
    limit_[t] = q0_ * n0_sq_[t];
    K_[t] = ks * (g.d[0].squaredNorm() + g.d[1].squaredNorm() + g.d[2].squaredNorm()) / 3.0;
  }
}

double AreaBarrierTerm::squared_area_ratio(const VecX& x, Index t) const {
  return geometry(*mesh_, x, t).n.squaredNorm() / n0_sq_[t];
}

std::vector<Index> AreaBarrierTerm::active_triangles(const VecX& x) const {
  // One cross product and comparison per triangle, on every force evaluation: nearly all
  // triangles are far from the onset, so one serial pass without a division or a second list is
  // cheaper than a parallel one (bench_assembly's BM_Forces times it).
  std::vector<Index> out;
  const Index nt = mesh_->num_triangles();
  for (Index t = 0; t < nt; ++t) {
    const auto& tr = mesh_->triangles[t];
    const Vec3 x0 = node(x, tr[0]);
    if ((node(x, tr[1]) - x0).cross(node(x, tr[2]) - x0).squaredNorm() < limit_[t])
      out.push_back(t);
  }
  return out;
}

double AreaBarrierTerm::energy(const State& s) const {
  double e = 0;
  for (Index t : active_triangles(s.x))
    e += cubic_barrier(K_[t], q0_, squared_area_ratio(s.x, t)).e;
  return e;
}

void AreaBarrierTerm::add_force(const State& s, VecX& f) const {
  // Serial over the few active triangles, in triangle order.
  for (Index t : active_triangles(s.x)) {
    const auto g = geometry(*mesh_, s.x, t);
    const double c = 1.0 / n0_sq_[t];
    const BarrierValue b = cubic_barrier(K_[t], q0_, c * g.n.squaredNorm());
    // F_i = -E'(q) dq/dx_i = -E'(q) 2 c n x d_i
    for (int i = 0; i < 3; ++i)
      f.segment<3>(3 * mesh_->triangles[t][i]) -= (2.0 * c * b.d1) * g.n.cross(g.d[i]);
  }
}

void AreaBarrierTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
  for (Index t : active_triangles(s.x)) {
    const auto g = geometry(*mesh_, s.x, t);
    const double c = 1.0 / n0_sq_[t];
    const BarrierValue b = cubic_barrier(K_[t], q0_, c * g.n.squaredNorm());
    std::array<Vec3, 3> grad;
    std::array<Mat3, 3> D;
    for (int i = 0; i < 3; ++i) {
      grad[i] = 2.0 * c * g.n.cross(g.d[i]);
      D[i] = cross_matrix(g.d[i]);
    }
    const Mat3 N = cross_matrix(g.n);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double sij = j == (i + 2) % 3 ? 1.0 : (j == (i + 1) % 3 ? -1.0 : 0.0);
        const Mat3 hess_q = 2.0 * c * (-D[i] * D[j] + sij * N);
        add_block(val, slots_[t][3 * i + j], b.d2 * grad[i] * grad[j].transpose() + b.d1 * hess_q);
      }
  }
}

void AreaBarrierTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  for (const auto& tr : mesh_->triangles)
    for (int a = 0; a < 3; ++a) out.emplace_back(tr[a], tr[(a + 1) % 3]);
}

void AreaBarrierTerm::bind(const BlockPattern& pattern) {
  slots_.resize(mesh_->num_triangles());
  for (Index t = 0; t < mesh_->num_triangles(); ++t) {
    const auto& tr = mesh_->triangles[t];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) slots_[t][3 * a + b] = pattern.slot(tr[a], tr[b]);
  }
}

}  // namespace crumple
