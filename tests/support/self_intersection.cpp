// Self-intersection count of a triangulated sheet (self_intersection.hpp).
#include "tests/support/self_intersection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>

namespace crumple::testing {

std::vector<std::pair<Index, Index>> self_intersections(const Mesh& mesh, const VecX& x) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const Index nt = mesh.num_triangles();
  std::vector<K::Triangle_3> tri(nt);
  std::vector<Eigen::AlignedBox3d> box(nt);
  for (Index t = 0; t < nt; ++t) {
    const auto& v = mesh.triangles[t];
    K::Point_3 p[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 q = node(x, v[k]);
      p[k] = K::Point_3(q.x(), q.y(), q.z());
      box[t].extend(q);
    }
    tri[t] = K::Triangle_3(p[0], p[1], p[2]);
  }
  // Sweep along x: only boxes overlapping in x are compared.
  std::vector<Index> order(nt);
  for (Index t = 0; t < nt; ++t) order[t] = t;
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return box[a].min().x() < box[b].min().x(); });
  std::vector<std::pair<Index, Index>> out;
  for (Index i = 0; i < nt; ++i) {
    const Index a = order[i];
    for (Index j = i + 1; j < nt && box[order[j]].min().x() <= box[a].max().x(); ++j) {
      const Index b = order[j];
      if (!box[a].intersects(box[b])) continue;
      bool adjacent = false;
      for (Index u : mesh.triangles[a])
        for (Index v : mesh.triangles[b]) adjacent = adjacent || u == v;
      if (!adjacent && CGAL::do_intersect(tri[a], tri[b])) out.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  return out;
}

std::size_t count_self_intersections(const Mesh& mesh, const VecX& x) {
  return self_intersections(mesh, x).size();
}

}  // namespace crumple::testing
