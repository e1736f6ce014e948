// Lloyd iterations with cells clipped by mirror images (lloyd.hpp).
#include "sim/mesh/lloyd.hpp"

#include <algorithm>

namespace crumple {

LloydStats lloyd_relax(const Domain& domain, std::vector<Point2>& interior, double spacing,
                       int iterations) {
  // A cell of a random start spans up to about 3.5 spacings (the largest empty circle of n
  // uniform points has area ~ A log n / n); 4 spacings clip even those, and the cells of the
  // relaxed points (about one spacing across) with a wide margin.
  const double reach = 4.0 * spacing;
  // Centroids of cells clipped to a convex outline are inside it; a point closer than this to
  // the outline could only come from a cell not fully clipped in an early, irregular iteration.
  const double margin = 1e-3 * spacing;
  const auto& fixed = domain.boundary_nodes();
  const Index n = static_cast<Index>(interior.size());

  LloydStats stats;
  std::vector<Point2> generators;
  for (int it = 0; it < iterations; ++it) {
    generators.assign(interior.begin(), interior.end());
    generators.insert(generators.end(), fixed.begin(), fixed.end());
    domain.append_mirrors(interior, reach, generators);
    const auto cells = voronoi_cells(generators, n);
    double max_move = 0.0;
    for (Index i = 0; i < n; ++i) {
      if (!cells[i].bounded) {  // not seen with mirrors within 4 spacings; then stay in place
        ++stats.unbounded;
        continue;
      }
      const Point2 c = domain.pulled_inside(cells[i].centroid, margin);
      if (c != cells[i].centroid) ++stats.pulled_back;
      max_move = std::max(max_move, (c - interior[i]).norm());
      interior[i] = c;
    }
    stats.iterations = it + 1;
    stats.last_max_move = max_move;
  }
  return stats;
}

}  // namespace crumple
