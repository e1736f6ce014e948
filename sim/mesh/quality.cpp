// Mesh quality figures (quality.hpp).
#include "sim/mesh/quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

namespace crumple {

MeshQuality mesh_quality(const Mesh& mesh) {
  MeshQuality q;
  q.nodes = mesh.num_nodes();
  q.triangles = mesh.num_triangles();
  q.edges = mesh.num_edges();
  q.hinges = mesh.num_hinges();
  q.boundary_nodes = static_cast<Index>(std::count(mesh.boundary.begin(), mesh.boundary.end(), 1));

  double min_angle = std::numbers::pi;
  q.min_area = std::numeric_limits<double>::infinity();
  q.max_area = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.ref.col(tri[k]);
      const Vec3 u = mesh.ref.col(tri[(k + 1) % 3]) - a, v = mesh.ref.col(tri[(k + 2) % 3]) - a;
      // atan2 of |u x v| and u.v is accurate for small angles, where acos is not.
      min_angle = std::min(min_angle, std::atan2(u.cross(v).norm(), u.dot(v)));
    }
    const double area = mesh.triangle_area(t);
    q.min_area = std::min(q.min_area, area);
    q.max_area = std::max(q.max_area, area);
  }
  q.min_angle_deg = min_angle * 180.0 / std::numbers::pi;

  if (mesh.num_edges() > 0) {
    const VecX& l = mesh.rest_length;
    q.mean_edge = l.mean();
    q.edge_cv = std::sqrt((l.array() - q.mean_edge).square().mean()) / q.mean_edge;
  }
  return q;
}

double mean_hinge_width(const Mesh& mesh) {
  if (mesh.hinges.empty()) return 0.0;
  double sum = 0.0;
  for (const Hinge& h : mesh.hinges)
    sum += (mesh.triangle_area(h.tris[0]) + mesh.triangle_area(h.tris[1])) / mesh.rest_length[h.edge];
  return sum / static_cast<double>(mesh.hinges.size());
}

double mean_index_gap(const Mesh& mesh) {
  if (mesh.edges.empty()) return 0.0;
  double s = 0.0;
  for (const auto& [i, j] : mesh.edges) s += std::abs(j - i);
  return s / static_cast<double>(mesh.edges.size());
}

}  // namespace crumple
