// Uniform Lloyd relaxation of the interior nodes of a sheet (paper §3.1): each iteration moves
// every interior point to the centroid of its Voronoi cell clipped to the outline, which drives
// random points towards a centroidal Voronoi tessellation (cells of nearly equal size and
// shape) and so gives nearly equilateral Delaunay triangles.
//
// The boundary nodes of the domain take part as fixed generators. Cells are clipped with
// mirror images of the points near the outline (domain.hpp), so one iteration is one Delaunay
// triangulation of n + O(sqrt n) points: O(n log n), not O(n^2).
#pragma once

#include "sim/mesh/domain.hpp"

namespace crumple {

struct LloydStats {
  int iterations = 0;
  double last_max_move = 0.0;  ///< largest displacement of a point in the last iteration
  Index pulled_back = 0;       ///< centroids that fell outside the outline and were pulled in
  Index unbounded = 0;         ///< cells left open by too few mirrors (their points stay put)
};

/// Relaxes `interior` (#I points strictly inside `domain`) in place by `iterations` Lloyd steps.
/// `spacing` is the mean node spacing: it sets how far from the outline points are mirrored
/// (a few spacings, more than a cell's size) and the margin that keeps points inside.
LloydStats lloyd_relax(const Domain& domain, std::vector<Point2>& interior, double spacing,
                       int iterations);

}  // namespace crumple
