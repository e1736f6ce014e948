// Square and disk outlines for mesh generation (domain.hpp).
#include "sim/mesh/domain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace crumple {

namespace {
double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}
}  // namespace

Domain::Domain(std::vector<Point2> corners, std::vector<Point2> nodes)
    : corners_(std::move(corners)), nodes_(std::move(nodes)) {
  // Start at the corner of smallest angle so the angles increase around the polygon.
  auto by_angle = [](const Point2& a, const Point2& b) {
    return std::atan2(a.y(), a.x()) < std::atan2(b.y(), b.x());
  };
  const auto first = std::min_element(corners_.begin(), corners_.end(), by_angle);
  std::rotate(corners_.begin(), first, corners_.end());
  for (const auto& c : corners_) angles_.push_back(std::atan2(c.y(), c.x()));
  const Index n = static_cast<Index>(corners_.size());
  inradius_ = std::numeric_limits<double>::infinity();
  min_side_ = std::numeric_limits<double>::infinity();
  for (Index k = 0; k < n; ++k) {
    const Point2 a = corners_[k], b = corners_[(k + 1) % n];
    inradius_ = std::min(inradius_, cross(b - a, -a) / (b - a).norm());
    min_side_ = std::min(min_side_, (b - a).norm());
  }
}

Domain Domain::square(double side, int per_side) {
  if (!(side > 0.0) || per_side < 1) throw std::invalid_argument("Domain::square: bad size");
  const double h = 0.5 * side;
  const std::vector<Point2> corners{{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  std::vector<Point2> nodes;
  for (int s = 0; s < 4; ++s) {
    const Point2 a = corners[s], b = corners[(s + 1) % 4];
    // Corners exactly, and no rounding drift along a side: interpolate from both ends.
    for (int k = 0; k < per_side; ++k) {
      const double t = static_cast<double>(k) / per_side;
      Point2 q = k == 0 ? a : Point2((1.0 - t) * a + t * b);
      // (1-t) a + t b does not return a coordinate that a and b share exactly (h = 0.05, say):
      // copy it, so the nodes of a side are exactly collinear and form the Delaunay hull.
      for (int d = 0; d < 2; ++d)
        if (a[d] == b[d]) q[d] = a[d];
      nodes.push_back(q);
    }
  }
  return Domain(corners, nodes);
}

Domain Domain::disk(double diameter, int count) {
  if (!(diameter > 0.0) || count < 3) throw std::invalid_argument("Domain::disk: bad size");
  const double r = 0.5 * diameter;
  std::vector<Point2> nodes;
  for (int k = 0; k < count; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / count;
    nodes.emplace_back(r * std::cos(phi), r * std::sin(phi));
  }
  return Domain(nodes, nodes);
}

double Domain::area() const {
  double a2 = 0.0;
  for (std::size_t k = 0; k < corners_.size(); ++k)
    a2 += cross(corners_[k], corners_[(k + 1) % corners_.size()]);
  return 0.5 * a2;
}

double Domain::inside_distance(const Point2& p) const {
  double d = std::numeric_limits<double>::infinity();
  const std::size_t n = corners_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 a = corners_[k], b = corners_[(k + 1) % n];
    d = std::min(d, cross(b - a, p - a) / (b - a).norm());
  }
  return d;
}

Point2 Domain::half_extent() const {
  Point2 e = Point2::Zero();
  for (const auto& c : corners_) e = e.cwiseMax(c.cwiseAbs());
  return e;
}

Index Domain::side_at_angle(const Point2& p) const {
  const double phi = std::atan2(p.y(), p.x());
  const auto it = std::upper_bound(angles_.begin(), angles_.end(), phi);
  const Index k = static_cast<Index>(it - angles_.begin()) - 1;
  return k < 0 ? static_cast<Index>(corners_.size()) - 1 : k;  // wedge across the -pi cut
}

// Calls f(a, b) for each side [a, b] within `reach` of p, looking only at the sides around the
// one facing p (a point near the outline is within reach of a few consecutive sides), so that
// the cost per point does not grow with the number of sides of a fine disk.
template <class F>
void Domain::for_sides_near(const Point2& p, double reach, F&& f) const {
  if (p.norm() < inradius_ - reach) return;
  const Index n = static_cast<Index>(corners_.size());
  const Index window = std::min<Index>(n / 2, static_cast<Index>(std::ceil(reach / min_side_)) + 1);
  const Index k0 = side_at_angle(p);
  for (Index j = -window; j <= window; ++j) {
    if (j == window && 2 * window == n) break;  // the side opposite k0, already visited
    const Index k = ((k0 + j) % n + n) % n;
    const Point2& a = corners_[k];
    const Point2& b = corners_[(k + 1) % n];
    if (segment_distance(p, a, b) < reach) f(a, b);
  }
}

void Domain::append_mirrors(const std::vector<Point2>& points, double reach,
                            std::vector<Point2>& out) const {
  // By index and by value: `out` may be `points` itself, and growing it moves its elements.
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 p = points[i];
    for_sides_near(p, reach, [&](const Point2& a, const Point2& b) {
      const Point2 ab = b - a;
      const Point2 foot = a + ((p - a).dot(ab) / ab.squaredNorm()) * ab;
      out.push_back(2.0 * foot - p);
    });
  }
}

Point2 Domain::pulled_inside(Point2 p, double margin) const {
  if (p.norm() < inradius_ - margin) return p;
  const Index n = static_cast<Index>(corners_.size());
  // Project onto each violated half-plane among the sides around the one facing p (a point is
  // never pulled from far away), twice, which settles a corner of the outline.
  const Index window = std::min<Index>(n / 2, 2);
  const Index k0 = side_at_angle(p);
  for (int sweep = 0; sweep < 2; ++sweep)
    for (Index j = -window; j <= window; ++j) {
      if (j == window && 2 * window == n) break;
      const Index k = ((k0 + j) % n + n) % n;
      const Point2 a = corners_[k], b = corners_[(k + 1) % n];
      const Point2 t = (b - a).normalized();
      const double d = cross(t, p - a);
      if (d < margin) p += (margin - d) * Point2(-t.y(), t.x());
    }
  return p;
}

}  // namespace crumple
