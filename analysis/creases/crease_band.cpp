// Creases summed across a band; see crease_band.hpp.
#include "analysis/creases/crease_band.hpp"

#include "analysis/creases/crease_edges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace crumple::analysis {

namespace {

constexpr double kParallelCos = 0.8660254037844387;  // cos 30 degrees

struct Segment2 {
  double ax, ay, tx, ty, len, mx, my;  // start, unit direction, length, midpoint
};

double fold_angle(double p) { return 2.0 * std::asin(std::clamp(p, -2.0, 2.0) / 2.0); }

}  // namespace

CreaseBand::CreaseBand(const MeshData& mesh, double width) : width_(width) {
  if (!(width > 0)) throw std::invalid_argument("CreaseBand: the width must be positive");
  const std::size_t nh = mesh.hinge_edge.size();
  std::vector<Segment2> seg(nh);
  double longest = 0;
  for (std::size_t h = 0; h < nh; ++h) {
    const auto& e = mesh.edges[static_cast<std::size_t>(mesh.hinge_edge[h])];
    const auto& a = mesh.ref_positions[static_cast<std::size_t>(e[0])];
    const auto& b = mesh.ref_positions[static_cast<std::size_t>(e[1])];
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    seg[h] = {a[0], a[1], dx / len, dy / len, len, 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    longest = std::max(longest, len);
  }
  // Midpoints in square cells of side `cell`: every midpoint beside h lies within
  // reach = hypot(len / 2, w / 2) of h's midpoint, so the cells within ceil(reach / cell) hold them.
  const double cell = std::max(width, longest);
  auto key = [](long i, long j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ (static_cast<std::uint64_t>(j) & 0xffffffffULL);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (std::size_t h = 0; h < nh; ++h)
    grid[key(std::lround(std::floor(seg[h].mx / cell)), std::lround(std::floor(seg[h].my / cell)))]
        .push_back(static_cast<int>(h));
  beside_.resize(nh);
  for (std::size_t h = 0; h < nh; ++h) {
    const Segment2& s = seg[h];
    const double reach = std::hypot(0.5 * s.len, 0.5 * width);
    const long r = static_cast<long>(std::ceil(reach / cell));
    const long ci = std::lround(std::floor(s.mx / cell)), cj = std::lround(std::floor(s.my / cell));
    for (long i = ci - r; i <= ci + r; ++i)
      for (long j = cj - r; j <= cj + r; ++j) {
        const auto it = grid.find(key(i, j));
        if (it == grid.end()) continue;
        for (int k : it->second) {
          const Segment2& o = seg[static_cast<std::size_t>(k)];
          if (std::abs(s.tx * o.tx + s.ty * o.ty) < kParallelCos) continue;
          const double rx = o.mx - s.ax, ry = o.my - s.ay;
          const double along = rx * s.tx + ry * s.ty, across = rx * s.ty - ry * s.tx;
          if (std::abs(across) <= 0.5 * width && along >= 0 && along <= s.len)
            beside_[h].push_back(k);
        }
      }
    std::sort(beside_[h].begin(), beside_[h].end());
  }
}

std::vector<char> CreaseBand::creased(const std::vector<double>& p, double threshold) const {
  if (p.size() != beside_.size())
    throw std::invalid_argument("CreaseBand::creased: one value per hinge expected");
  const double limit = fold_angle(threshold);
  std::vector<char> out(p.size(), 0);
  for (std::size_t h = 0; h < p.size(); ++h) {
    if (p[h] == 0) continue;
    // Only folds of h's own sense add up: a mountain fold beside a valley fold is two creases
    // (each on its own angle), not a cancelled one.
    double sum = 0;
    for (int k : beside_[h]) {
      const double q = p[static_cast<std::size_t>(k)];
      if ((q > 0) == (p[h] > 0) && q != 0) sum += std::abs(fold_angle(q));
    }
    out[h] = sum > limit;
  }
  return out;
}

std::vector<char> select_creases(const std::vector<double>& p, double threshold,
                                 const CreaseBand* band) {
  return band ? band->creased(p, threshold) : crease_hinges(p, threshold);
}

}  // namespace crumple::analysis
