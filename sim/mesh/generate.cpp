// Mesh generation pipeline: node budget, random start, Lloyd, Delaunay, Hilbert order
// (generate.hpp).
#include "sim/mesh/generate.hpp"

#include "sim/mesh/delaunay_cgal.hpp"
#include "sim/mesh/domain.hpp"
#include "sim/mesh/lloyd.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace crumple {

namespace {

struct Layout {
  Domain domain;
  double spacing;  // mean node spacing h
};

// Splits the node budget between the outline and the interior. A triangulation of nearly
// equilateral triangles of side h with n_b boundary and n_i interior nodes has 2 n_i + n_b - 2
// triangles of area (sqrt 3 / 4) h^2, so n = n_i + n_b ~ 2A / (sqrt 3 h^2) + P / (2h) for area
// A and perimeter P: solved for 1/h, then the boundary count rounded, the interior the rest.
Layout layout(const MeshSpec& spec) {
  const bool square = spec.shape == "square";
  const double a = square ? spec.size * spec.size : std::numbers::pi * spec.size * spec.size / 4;
  const double p = square ? 4.0 * spec.size : std::numbers::pi * spec.size;
  const double qa = 2.0 * a / std::sqrt(3.0), qb = 0.5 * p;
  const double inv_h = (-qb + std::sqrt(qb * qb + 4.0 * qa * spec.nodes)) / (2.0 * qa);
  if (square) {
    const int per_side = std::max(1, static_cast<int>(std::lround(spec.size * inv_h)));
    return {Domain::square(spec.size, per_side), spec.size / per_side};
  }
  const int count = std::max(3, static_cast<int>(std::lround(p * inv_h)));
  return {Domain::disk(spec.size, count), 1.0 / inv_h};
}

// Uniform double in [0, 1) from the top 53 bits: the same numbers on every standard library
// (std::uniform_real_distribution is implementation-defined).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniform points in the outline shrunk by a quarter spacing (so no start point sits on a
// boundary node), by rejection from the bounding box.
std::vector<Point2> random_interior(const Domain& domain, Index count, double spacing,
                                    std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Point2 ext = domain.half_extent();
  std::vector<Point2> pts;
  pts.reserve(count);
  while (static_cast<Index>(pts.size()) < count) {
    const Point2 p((2.0 * unit(rng) - 1.0) * ext.x(), (2.0 * unit(rng) - 1.0) * ext.y());
    if (domain.contains(p, 0.25 * spacing)) pts.push_back(p);
  }
  return pts;
}

}  // namespace

const std::vector<std::string>& mesh_shapes() {
  static const std::vector<std::string> shapes{"disk", "square"};
  return shapes;
}

Mesh generate_mesh(const MeshSpec& spec) {
  const auto& shapes = mesh_shapes();
  if (std::find(shapes.begin(), shapes.end(), spec.shape) == shapes.end()) {
    std::string valid;
    for (const auto& s : shapes) valid += (valid.empty() ? "" : ", ") + s;
    throw std::invalid_argument("mesh.shape: unknown shape '" + spec.shape + "' (valid: " +
                                valid + ")");
  }
  if (spec.nodes < 10)
    throw std::invalid_argument("mesh.nodes: at least 10 nodes, got " + std::to_string(spec.nodes));
  if (!(spec.size > 0.0) || !std::isfinite(spec.size))
    throw std::invalid_argument("mesh.size: must be positive and finite");
  if (spec.lloyd_iterations < 0)
    throw std::invalid_argument("mesh.lloyd_iterations: must be >= 0");

  const auto [domain, spacing] = layout(spec);
  const auto& fixed = domain.boundary_nodes();
  const Index n_fixed = static_cast<Index>(fixed.size());
  const Index n_free = std::max<Index>(1, spec.nodes - n_fixed);
  std::vector<Point2> points = random_interior(domain, n_free, spacing, spec.seed);
  lloyd_relax(domain, points, spacing, spec.lloyd_iterations);
  points.insert(points.end(), fixed.begin(), fixed.end());  // interior first, then the outline

  const Index n = static_cast<Index>(points.size());
  Eigen::Matrix3Xd ref(3, n);
  for (Index i = 0; i < n; ++i) ref.col(i) = Vec3(points[i].x(), points[i].y(), 0.0);
  const Mesh mesh = build_mesh(std::move(ref), delaunay_triangles(points), spec.shape);

  // The interior points are strictly inside the convex outline, so the Delaunay hull must be
  // the polygon of boundary nodes: no hull sliver, no interior node on the border.
  Index border_edges = 0;
  for (const auto& et : mesh.edge_triangles) border_edges += et[1] < 0;
  for (Index i = 0; i < n; ++i)
    if (mesh.boundary[i] != (i >= n - n_fixed) || border_edges != n_fixed)
      throw std::logic_error("generate_mesh: Delaunay hull differs from the boundary polygon");

  // Hilbert renumbering: order[k] is the old index of new node k.
  const std::vector<Index> order = hilbert_order(points);
  std::vector<Index> perm(n);
  for (Index k = 0; k < n; ++k) perm[order[k]] = k;
  return renumber_nodes(mesh, perm);
}

}  // namespace crumple
