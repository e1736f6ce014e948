// Raster frame and sheet geometry; see raster_frame.hpp.
#include "analysis/raster/raster_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::analysis {
namespace {

double triangle_area(const MeshData& m, const std::array<std::int32_t, 3>& t) {
  const auto& a = m.ref_positions[static_cast<std::size_t>(t[0])];
  const auto& b = m.ref_positions[static_cast<std::size_t>(t[1])];
  const auto& c = m.ref_positions[static_cast<std::size_t>(t[2])];
  return 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

}  // namespace

RasterFrame make_frame(const MeshData& mesh, double px_per_unit, int margin) {
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& p : mesh.ref_positions)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  RasterFrame f;
  f.px_per_unit = px_per_unit;
  f.x0 = lo[0];
  f.y0 = lo[1];
  f.margin = margin;
  f.width = static_cast<int>(std::ceil((hi[0] - lo[0]) * px_per_unit)) + 2 * margin + 1;
  f.height = static_cast<int>(std::ceil((hi[1] - lo[1]) * px_per_unit)) + 2 * margin + 1;
  return f;
}

double sheet_area(const MeshData& mesh) {
  double a = 0.0;
  for (const auto& t : mesh.triangles) a += triangle_area(mesh, t);
  return a;
}

double sheet_size(const MeshData& mesh) {
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& p : mesh.ref_positions)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

double mean_triangle_area(const MeshData& mesh) {
  return mesh.triangles.empty() ? 0.0 : sheet_area(mesh) / static_cast<double>(mesh.triangles.size());
}

}  // namespace crumple::analysis
