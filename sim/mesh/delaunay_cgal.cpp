// CGAL behind delaunay_cgal.hpp: the only translation unit of the project that includes CGAL.
#include "sim/mesh/delaunay_cgal.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <stdexcept>
#include <type_traits>
#include <utility>

namespace crumple {

namespace {
// Exact predicates keep the triangulation valid for nearly cocircular points (mirror images
// make many exactly cocircular quadruples); constructions (circumcentres) need only doubles.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
using Fb = CGAL::Triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
using CPoint = K::Point_2;

Delaunay triangulate(const std::vector<Point2>& points) {
  std::vector<std::pair<CPoint, Index>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(CPoint(points[i].x(), points[i].y()), static_cast<Index>(i));
  Delaunay dt;
  // The range insert sorts spatially with a fixed-seed shuffle, so the result is reproducible.
  dt.insert(input.begin(), input.end());
  if (dt.number_of_vertices() != points.size())
    throw std::invalid_argument("delaunay: duplicate points in the input");
  return dt;
}
}  // namespace

std::vector<std::array<Index, 3>> delaunay_triangles(const std::vector<Point2>& points) {
  const Delaunay dt = triangulate(points);
  std::vector<std::array<Index, 3>> tris;
  tris.reserve(dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    tris.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return tris;
}

std::vector<VoronoiCell> voronoi_cells(const std::vector<Point2>& points, Index count) {
  if (count < 0 || count > static_cast<Index>(points.size()))
    throw std::invalid_argument("voronoi_cells: count out of range");
  const Delaunay dt = triangulate(points);
  std::vector<VoronoiCell> cells(count);
  std::vector<Point2> ring;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const Index i = v->info();
    if (i >= count) continue;
    const Point2 p = points[i];
    VoronoiCell& cell = cells[i];
    cell.centroid = p;
    // The cell's corners are the circumcentres of the incident triangles, met counter-clockwise.
    ring.clear();
    bool bounded = true;
    auto fc = dt.incident_faces(v), done = fc;
    do {
      if (dt.is_infinite(fc)) {
        bounded = false;
        break;
      }
      const CPoint c = dt.circumcenter(fc);
      ring.emplace_back(c.x() - p.x(), c.y() - p.y());  // relative to p: less cancellation
    } while (++fc != done);
    if (!bounded) continue;
    // Shoelace formulas for the area and first moments of the polygon.
    double a2 = 0.0, mx = 0.0, my = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point2& u = ring[k];
      const Point2& w = ring[(k + 1) % ring.size()];
      const double cr = u.x() * w.y() - w.x() * u.y();
      a2 += cr;
      mx += (u.x() + w.x()) * cr;
      my += (u.y() + w.y()) * cr;
    }
    cell.bounded = true;
    cell.area = 0.5 * a2;
    if (a2 > 0.0) cell.centroid = p + Point2(mx, my) / (3.0 * a2);
  }
  return cells;
}

std::vector<Index> hilbert_order(const std::vector<Point2>& points) {
  std::vector<CPoint> cp;
  cp.reserve(points.size());
  for (const auto& p : points) cp.emplace_back(p.x(), p.y());
  // The adapter sorts keys of the property map (std::size_t indices into cp) by their points.
  std::vector<std::size_t> keys(points.size());
  for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = i;
  const auto map = CGAL::make_property_map(cp);
  using Traits = CGAL::Spatial_sort_traits_adapter_2<K, std::remove_const_t<decltype(map)>>;
  // hilbert_sort shuffles with a default-seeded generator first: reproducible.
  CGAL::hilbert_sort(keys.begin(), keys.end(), Traits(map));
  return std::vector<Index>(keys.begin(), keys.end());
}

}  // namespace crumple
