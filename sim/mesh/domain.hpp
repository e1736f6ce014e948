// The outline of a flat sheet for mesh generation (paper §3.1): a convex polygon centred at the
// origin, with the fixed boundary nodes placed along it at (about) the mean node spacing.
//
// Two outlines: a square (its four corners are the polygon, boundary nodes evenly spaced along
// the sides, corners included) and a disk (the polygon is the regular polygon of its boundary
// nodes, so the meshed area is that inscribed polygon's area). Lloyd iterations use the outline
// to clip Voronoi cells (mirror images across nearby sides) and to keep points strictly inside.
#pragma once

#include "sim/mesh/delaunay_cgal.hpp"

#include <vector>

namespace crumple {

class Domain {
 public:
  /// Square of side `side`, `per_side` >= 1 boundary intervals on each side (4 per_side nodes).
  static Domain square(double side, int per_side);
  /// Disk of diameter `diameter`, `count` >= 3 boundary nodes evenly spaced on the circle.
  static Domain disk(double diameter, int count);

  /// Boundary nodes, counter-clockwise; they stay fixed while the interior is relaxed.
  const std::vector<Point2>& boundary_nodes() const { return nodes_; }
  /// Area enclosed by the polygon (square: side^2; disk: inscribed polygon).
  double area() const;
  /// Signed distance from p to the outline, positive inside (exact for the convex polygon).
  double inside_distance(const Point2& p) const;
  /// Half-widths of the axis-aligned bounding box (the polygon lies in [-hx,hx] x [-hy,hy]).
  Point2 half_extent() const;

  /// Appends to `out` the mirror image of each p in `points` across every side whose segment
  /// lies closer to p than `reach`. With reach above the size of a Voronoi cell, the cell of
  /// each point among points + mirrors is its Voronoi cell clipped to the polygon: each side is
  /// the bisector of a point and its mirror, and a mirror is never nearer to a place inside the
  /// (convex) polygon than its original. `out` may be `points` itself.
  void append_mirrors(const std::vector<Point2>& points, double reach,
                      std::vector<Point2>& out) const;

  /// True if p lies at least `margin` inside every side.
  bool contains(const Point2& p, double margin) const { return pulled_inside(p, margin) == p; }
  /// p moved inward, if needed, so that it lies at least `margin` inside every side.
  Point2 pulled_inside(Point2 p, double margin) const;

 private:
  explicit Domain(std::vector<Point2> corners, std::vector<Point2> nodes);
  Index side_at_angle(const Point2& p) const;  // the side whose wedge from the origin holds p
  template <class F>
  void for_sides_near(const Point2& p, double reach, F&& f) const;

  std::vector<Point2> corners_;  // polygon vertices, counter-clockwise, by increasing angle
  std::vector<double> angles_;   // atan2 of each corner, increasing
  std::vector<Point2> nodes_;
  double inradius_ = 0.0;        // the disk of this radius about the origin is inside
  double min_side_ = 0.0;
};

}  // namespace crumple
