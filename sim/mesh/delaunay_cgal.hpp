// The planar computational-geometry kernels of mesh generation (paper §3.1): 2D Delaunay
// triangulation, centroids of Voronoi cells for Lloyd iterations, and Hilbert-curve ordering.
//
// A plain interface over CGAL. CGAL's triangulation headers are slow to compile and heavy, so
// they are included by delaunay_cgal.cpp alone; the rest of the project sees only Eigen types.
#pragma once

#include "sim/core/types.hpp"

#include <vector>

namespace crumple {

using Point2 = Eigen::Vector2d;

/// Delaunay triangulation of `points` (#P points, distinct). Returns the finite triangles as
/// indices into `points`, each counter-clockwise. Collinear points on the convex hull stay
/// vertices of the hull; no zero-area triangle is produced. Deterministic for given input.
std::vector<std::array<Index, 3>> delaunay_triangles(const std::vector<Point2>& points);

/// A Voronoi cell of one generator: its area and centroid.
struct VoronoiCell {
  double area = 0.0;
  Point2 centroid = Point2::Zero();
  bool bounded = false;  ///< false if the cell is unbounded (generator on the convex hull)
};

/// Voronoi cells of generators points[0..count) in the diagram of all `points`; the generators
/// points[count..) take part (e.g. mirror images that clip the cells to a domain) but their own
/// cells are not computed. An unbounded cell is reported with bounded = false, zero area and
/// its generator as centroid. Cost O(#P log #P).
std::vector<VoronoiCell> voronoi_cells(const std::vector<Point2>& points, Index count);

/// A permutation of 0..#P-1 listing `points` along a Hilbert space-filling curve (CGAL's
/// hilbert_sort, median policy): order[k] is the index of the k-th point on the curve.
std::vector<Index> hilbert_order(const std::vector<Point2>& points);

}  // namespace crumple
