// Mesh topology: edges, hinges and boundary flags derived from a triangle list (mesh.hpp).
#include "sim/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace crumple {

namespace {
std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}
double signed_area_xy(const Eigen::Matrix3Xd& p, const std::array<Index, 3>& t) {
  const Vec3 a = p.col(t[0]), b = p.col(t[1]), c = p.col(t[2]);
  return 0.5 * ((b - a).cross(c - a)).z();
}
}  // namespace

double Mesh::triangle_area(Index t) const {
  const auto& tri = triangles[t];
  const Vec3 a = ref.col(tri[0]), b = ref.col(tri[1]), c = ref.col(tri[2]);
  return 0.5 * (b - a).cross(c - a).norm();
}

double Mesh::total_area() const {
  double s = 0.0;
  for (Index t = 0; t < num_triangles(); ++t) s += triangle_area(t);
  return s;
}

double Mesh::mean_edge_length() const {
  return rest_length.size() ? rest_length.mean() : 0.0;
}

Mesh build_mesh(Eigen::Matrix3Xd ref, std::vector<std::array<Index, 3>> triangles,
                std::string shape) {
  Mesh m;
  m.ref = std::move(ref);
  m.shape = std::move(shape);
  const Index n = m.num_nodes();
  for (auto& t : triangles) {
    for (Index v : t)
      if (v < 0 || v >= n) throw std::invalid_argument("build_mesh: triangle node out of range");
    if (signed_area_xy(m.ref, t) < 0) std::swap(t[1], t[2]);
  }
  m.triangles = std::move(triangles);

  // Edges in order of first appearance, each with its one or two triangles.
  std::unordered_map<std::uint64_t, Index> index;
  index.reserve(3 * m.triangles.size());
  m.triangle_edges.resize(m.triangles.size());
  for (Index t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Index a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];
      auto [it, fresh] = index.try_emplace(edge_key(a, b), m.num_edges());
      if (fresh) {
        m.edges.push_back({std::min(a, b), std::max(a, b)});
        m.edge_triangles.push_back({t, -1});
      } else {
        auto& et = m.edge_triangles[it->second];
        if (et[1] != -1) throw std::invalid_argument("build_mesh: edge shared by more than two triangles");
        et[1] = t;
      }
      m.triangle_edges[t][k] = it->second;
    }
  }

  m.rest_length.resize(m.num_edges());
  m.boundary.assign(n, 0);
  m.edge_hinge.assign(m.num_edges(), -1);
  for (Index e = 0; e < m.num_edges(); ++e) {
    const auto [i, j] = m.edges[e];
    m.rest_length[e] = (m.ref.col(i) - m.ref.col(j)).norm();
    const auto [t1, t2] = m.edge_triangles[e];
    if (t2 < 0) {
      m.boundary[i] = m.boundary[j] = 1;
      continue;
    }
    // Orient the hinge so that T1 = (x0, x1, x2) is counter-clockwise.
    const auto& tri1 = m.triangles[t1];
    int k = 0;
    while (tri1[k] == i || tri1[k] == j) ++k;  // k: vertex of T1 opposite the edge
    Hinge h;
    h.nodes[0] = tri1[(k + 1) % 3];
    h.nodes[1] = tri1[(k + 2) % 3];
    h.nodes[2] = tri1[k];
    const auto& tri2 = m.triangles[t2];
    for (Index v : tri2)
      if (v != i && v != j) h.nodes[3] = v;
    h.edge = e;
    h.tris = {t1, t2};
    const double abar = m.triangle_area(t1) + m.triangle_area(t2);
    const double l = m.rest_length[e];
    h.rest_factor = std::sqrt(3.0) * l * l / (2.0 * abar);
    m.edge_hinge[e] = m.num_hinges();
    m.hinges.push_back(h);
  }
  return m;
}

Mesh renumber_nodes(const Mesh& mesh, const std::vector<Index>& perm) {
  const Index n = mesh.num_nodes();
  if (static_cast<Index>(perm.size()) != n) throw std::invalid_argument("renumber_nodes: size");
  Eigen::Matrix3Xd ref(3, n);
  for (Index i = 0; i < n; ++i) ref.col(perm[i]) = mesh.ref.col(i);
  auto tris = mesh.triangles;
  for (auto& t : tris)
    for (auto& v : t) v = perm[v];
  return build_mesh(std::move(ref), std::move(tris), mesh.shape);
}

}  // namespace crumple
