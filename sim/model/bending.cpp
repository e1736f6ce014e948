// Bending with plastic rest curvature (bending.hpp, paper eq. 15 and Appendix B.4).
#include "sim/model/bending.hpp"

#include "sim/model/edge_colors.hpp"

#include <cmath>

namespace crumple {

BendingTerm::BendingTerm(const Mesh& mesh, double kb, Assembly assembly)
    : mesh_(&mesh),
      kb_(kb),
      assembly_(assembly),
      hinge_colors_(color_hinges(mesh)),
      tri_colors_(color_triangles(mesh)) {
  // T1 = (x0, x1, x2) and T2 = (x1, x0, x3) must be cyclic rotations of the mesh's triangles,
  // so that the triangles' own normals are the wings' normals.
  const auto rotation_of = [](const std::array<Index, 3>& tri, Index a, Index b, Index c) {
    for (int k = 0; k < 3; ++k)
      if (tri[k] == a && tri[(k + 1) % 3] == b && tri[(k + 2) % 3] == c) return true;
    return false;
  };
  oriented_ = true;
  for (const auto& hg : mesh.hinges) {
    const auto& nd = hg.nodes;
    if (!rotation_of(mesh.triangles[hg.tris[0]], nd[0], nd[1], nd[2]) ||
        !rotation_of(mesh.triangles[hg.tris[1]], nd[1], nd[0], nd[3])) {
      oriented_ = false;
      break;
    }
  }
  set_assembly(assembly);
}

void BendingTerm::update_frames(const VecX& x) const {
  const Index nt = mesh_->num_triangles();
  frames_.resize(nt);
#pragma omp parallel for schedule(static)
  for (Index t = 0; t < nt; ++t) {
    const auto& tri = mesh_->triangles[t];
    frames_[t] = triangle_frame(node(x, tri[0]), node(x, tri[1]), node(x, tri[2]));
  }
}

HalfAngle BendingTerm::hinge_gradient(const VecX& x, Index h, Vec12& grad) const {
  const auto& hg = mesh_->hinges[h];
  const auto& nd = hg.nodes;
  const Vec3 x0 = node(x, nd[0]), x1 = node(x, nd[1]), x2 = node(x, nd[2]), x3 = node(x, nd[3]);
  return oriented_ ? bend_half_angle_gradient(x0, x1, x2, x3, frames_[hg.tris[0]],
                                              frames_[hg.tris[1]], grad)
                   : bend_half_angle_derivatives(x0, x1, x2, x3, grad, nullptr);
}

void BendingTerm::update_cache(const State& s) const {
  const Index nh = mesh_->num_hinges();
  cache_.resize(nh);
  curvature_.resize(nh);
  if (oriented_) update_frames(s.x);
#pragma omp parallel for schedule(static)
  for (Index h = 0; h < nh; ++h) {
    HingeCache& c = cache_[h];
    const HalfAngle ha = hinge_gradient(s.x, h, c.grad);
    const double sh = ha.sin_half, ch = ha.cos_half;
    c.cos_half = ch;
    curvature_[h] = 2.0 * sh;
    const double k = kb_ * mesh_->hinges[h].rest_factor;
    const double d = curvature_[h] - s.p[h];
    c.zeta = k * d * ch;
    c.xi = k * (ch * ch - 0.5 * d * sh);
  }
}

double BendingTerm::energy(const State& s) const {
  double e = 0.0;
  const Index nh = mesh_->num_hinges();
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (Index h = 0; h < nh; ++h) {
    const auto& hg = mesh_->hinges[h];
    const auto& nd = hg.nodes;
    const double d =
        hinge_curvature(node(s.x, nd[0]), node(s.x, nd[1]), node(s.x, nd[2]), node(s.x, nd[3])) -
        s.p[h];
    e += 0.5 * kb_ * hg.rest_factor * d * d;
  }
  return e;
}

void BendingTerm::add_force(const State& s, VecX& f) const {
  // The force needs only zeta grad(theta) once per hinge: computed where it is scattered, it is
  // never written to and read back from the hinge cache (128 bytes per hinge), which the
  // Jacobians alone need. The curvatures are kept for last_curvatures().
  const Index nh = mesh_->num_hinges();
  curvature_.resize(nh);
  if (oriented_) update_frames(s.x);
  for_each_colored(hinge_colors_, [&](Index h) {
    const auto& hg = mesh_->hinges[h];
    Vec12 grad;
    const HalfAngle ha = hinge_gradient(s.x, h, grad);
    const double c = 2.0 * ha.sin_half;
    curvature_[h] = c;
    const double zeta = kb_ * hg.rest_factor * (c - s.p[h]) * ha.cos_half;
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * hg.nodes[a]) -= zeta * grad.segment<3>(3 * a);
  });
}

void BendingTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
  if (assembly_ == Assembly::PerHinge) {
    // Per hinge: gradient and Hessian of theta for the whole stencil, then 16 blocks.
    const bool with_hp = J.Hp.rows() == 3 * mesh_->num_nodes();
    if (with_hp) update_cache(s);
    for_each_colored(hinge_colors_, [&](Index h) {
      const auto& hg = mesh_->hinges[h];
      const auto& nd = hg.nodes;
      Vec12 g;
      Mat12 H;
      const HalfAngle ha = bend_half_angle_derivatives(node(s.x, nd[0]), node(s.x, nd[1]),
                                                       node(s.x, nd[2]), node(s.x, nd[3]), g, &H);
      const double k = kb_ * hg.rest_factor;
      const double d = 2.0 * ha.sin_half - s.p[h];
      H *= k * d * ha.cos_half;
      H.noalias() += (k * (ha.cos_half * ha.cos_half - 0.5 * d * ha.sin_half)) * g * g.transpose();
      const auto& sl = hinge_slots_[h];
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) add_block(val, sl[4 * a + b], H.block<3, 3>(3 * a, 3 * b));
    });
  } else {
    update_cache(s);
    // Per triangle (docs/MODEL.md §4.5): each triangle sums, over its interior edges,
    // the zeta-weighted half-hinge terms into S_a (scalars) and G_ab (in-plane vectors), and the
    // part of xi grad(theta) grad(theta)^T whose two nodes lie in this triangle into local
    // blocks (pairs on the hinge edge are taken by T1 only); its 9 blocks, S_a dn_b n^T +
    // n G_ab^T + local, are written once. A hinge pass then adds only the two blocks that couple
    // x2 and x3, which share no triangle.
    for_each_colored(tri_colors_, [&](Index t) {
      const auto& tri = mesh_->triangles[t];
      double S[3] = {0, 0, 0};
      Vec3 G[3][3];
      Mat3 L[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          G[a][b].setZero();
          L[a][b].setZero();
        }
      HalfHinge hh;
      bool any = false;
      for (int k = 0; k < 3; ++k) {
        const Index hinge = mesh_->edge_hinge[mesh_->triangle_edges[t][k]];
        if (hinge < 0) continue;
        const int loc[3] = {(k + 1) % 3, (k + 2) % 3, k};  // half-hinge (p, q, r) -> vertex
        half_hinge(node(s.x, tri[loc[0]]), node(s.x, tri[loc[1]]), node(s.x, tri[loc[2]]), hh,
                   true);
        const HingeCache& hc = cache_[hinge];
        const bool first = mesh_->hinges[hinge].tris[0] == t;
        // Half-hinge (p, q, r) is (x0, x1, x2) in T1 and (x1, x0, x3) in T2.
        const int hidx[3] = {first ? 0 : 1, first ? 1 : 0, first ? 2 : 3};
        for (int a = 0; a < 3; ++a) {
          S[loc[a]] += hc.zeta * hh.s[a];
          const Vec3 ga = hc.xi * hc.grad.segment<3>(3 * hidx[a]);
          for (int b = 0; b < 3; ++b) {
            G[loc[a]][loc[b]] += hc.zeta * hh.ds[a][b];
            if (!first && a < 2 && b < 2) continue;
            L[loc[a]][loc[b]].noalias() += ga * hc.grad.segment<3>(3 * hidx[b]).transpose();
          }
        }
        any = true;
      }
      if (!any) return;
      // dn for vertex v: n x (opposite edge, counter-clockwise) / 2A, the same for every edge.
      // The triangle's frame from update_cache above (this assembly implies an oriented mesh).
      const Vec3 x0 = node(s.x, tri[0]), x1 = node(s.x, tri[1]), x2 = node(s.x, tri[2]);
      const Vec3& n = frames_[t].n;
      const double a2 = frames_[t].a2;
      const Vec3 dn[3] = {n.cross(x1 - x2) / a2, n.cross(x2 - x0) / a2, n.cross(x0 - x1) / a2};
      const auto& sl = tri_slots_[t];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          L[a][b].noalias() += S[a] * dn[b] * n.transpose();
          L[a][b].noalias() += n * G[a][b].transpose();
          add_block(val, sl[3 * a + b], L[a][b]);
        }
    });
    for_each_colored(hinge_colors_, [&](Index h) {
      const HingeCache& c = cache_[h];
      const Mat3 B = c.xi * c.grad.segment<3>(6) * c.grad.segment<3>(9).transpose();
      add_block(val, hinge_slots_[h][4 * 2 + 3], B);
      add_block(val, hinge_slots_[h][4 * 3 + 2], B.transpose());
    });
  }

  const Index nh = mesh_->num_hinges();
  if (J.Hp.rows() == 3 * mesh_->num_nodes() && J.Hp.cols() == nh) {
    // Hp = -dF/dp = -kb f dc/dx, one column of 12 entries per hinge.
    std::vector<Eigen::Triplet<double, int>> trip;
    trip.reserve(12 * nh);
    for (Index h = 0; h < nh; ++h) {
      const auto& hg = mesh_->hinges[h];
      const double w = -kb_ * hg.rest_factor * cache_[h].cos_half;
      for (int a = 0; a < 4; ++a)
        for (int d = 0; d < 3; ++d)
          trip.emplace_back(3 * hg.nodes[a] + d, h, w * cache_[h].grad[3 * a + d]);
    }
    SpMatCol hp(J.Hp.rows(), nh);
    hp.setFromTriplets(trip.begin(), trip.end());
    J.Hp += hp;
  }
}

const VecX& BendingTerm::last_curvatures() const { return curvature_; }

void BendingTerm::curvatures(const VecX& x, VecX& c) const {
  const Index nh = mesh_->num_hinges();
  c.resize(nh);
#pragma omp parallel for schedule(static)
  for (Index h = 0; h < nh; ++h) {
    const auto& nd = mesh_->hinges[h].nodes;
    c[h] = hinge_curvature(node(x, nd[0]), node(x, nd[1]), node(x, nd[2]), node(x, nd[3]));
  }
}

void BendingTerm::curvature_gradients(const VecX& x, VecX& c, std::vector<Vec12>& grad) const {
  const Index nh = mesh_->num_hinges();
  c.resize(nh);
  grad.resize(nh);
#pragma omp parallel for schedule(static)
  for (Index h = 0; h < nh; ++h) {
    const auto& nd = mesh_->hinges[h].nodes;
    const HalfAngle ha = bend_half_angle_derivatives(node(x, nd[0]), node(x, nd[1]),
                                                     node(x, nd[2]), node(x, nd[3]), grad[h],
                                                     nullptr);
    c[h] = 2.0 * ha.sin_half;
    grad[h] *= ha.cos_half;
  }
}

void BendingTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  for (const auto& hg : mesh_->hinges)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) out.emplace_back(hg.nodes[a], hg.nodes[b]);
}

void BendingTerm::bind(const BlockPattern& p) {
  hinge_slots_.resize(mesh_->num_hinges());
  for (Index h = 0; h < mesh_->num_hinges(); ++h) {
    const auto& nd = mesh_->hinges[h].nodes;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) hinge_slots_[h][4 * a + b] = p.slot(nd[a], nd[b]);
  }
  tri_slots_.resize(mesh_->num_triangles());
  for (Index t = 0; t < mesh_->num_triangles(); ++t) {
    const auto& tri = mesh_->triangles[t];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) tri_slots_[t][3 * a + b] = p.slot(tri[a], tri[b]);
  }
}

}  // namespace crumple
