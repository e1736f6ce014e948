// Uniform-grid pair search (pair_search.hpp).
#include "sim/contact/pair_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace crumple {

namespace {

constexpr Index kBlock = 256;  // points per work unit: small enough to balance, big enough to amortise

struct Grid {
  std::array<int, 3> n{1, 1, 1};
  Vec3 lo = Vec3::Zero();
  Vec3 inv_w = Vec3::Zero();  // 1 / cell width (0 in a flat direction)

  int coord(const Vec3& p, int d) const {
    const int c = static_cast<int>((p[d] - lo[d]) * inv_w[d]);
    return std::clamp(c, 0, n[d] - 1);
  }
  long cell(int x, int y, int z) const { return (static_cast<long>(z) * n[1] + y) * n[0] + x; }
};

Grid make_grid(const Eigen::Matrix3Xd& pos, double cutoff) {
  Grid g;
  g.lo = pos.rowwise().minCoeff();
  const Vec3 ext = pos.rowwise().maxCoeff() - g.lo;
  const double max_cells = 4.0 * static_cast<double>(pos.cols()) + 64.0;
  double w = cutoff;
  for (;;) {
    double total = 1.0;
    for (int d = 0; d < 3; ++d) total *= std::max(1.0, std::floor(ext[d] / w));
    if (total <= max_cells) break;
    w *= std::cbrt(total / max_cells) * 1.01;
  }
  for (int d = 0; d < 3; ++d) {
    g.n[d] = static_cast<int>(std::max(1.0, std::floor(ext[d] / w)));
    // Width ext/n >= w >= cutoff; a zero extent keeps one cell and inv_w = 0.
    g.inv_w[d] = ext[d] > 0 ? g.n[d] / ext[d] : 0.0;
  }
  return g;
}

}  // namespace

ContactPairs find_pairs(const Eigen::Matrix3Xd& pos, double cutoff, const ContactSites* sites) {
  if (!(cutoff > 0.0)) throw std::invalid_argument("find_pairs: cutoff must be positive");
  const Index m = static_cast<Index>(pos.cols());
  if (sites && sites->size() != m)
    throw std::invalid_argument("find_pairs: sites and positions differ in size");
  ContactPairs out;
  if (m < 2) return out;

  const Grid g = make_grid(pos, cutoff);
  const long ncells = static_cast<long>(g.n[0]) * g.n[1] * g.n[2];
  out.stats.dims = g.n;
  out.stats.cell = cutoff;
  for (int d = 0; d < 3; ++d)
    if (g.inv_w[d] > 0) out.stats.cell = std::min(out.stats.cell, 1.0 / g.inv_w[d]);
  if (out.stats.cell < cutoff) out.stats.cell = cutoff;  // flat directions: one cell, any width

  // Counting sort of the points by cell (stable: index order inside a cell).
  std::vector<std::array<int, 3>> coords(m);
  std::vector<long> cell_of(m);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < m; ++i) {
    const Vec3 p = pos.col(i);
    coords[i] = {g.coord(p, 0), g.coord(p, 1), g.coord(p, 2)};
    cell_of[i] = g.cell(coords[i][0], coords[i][1], coords[i][2]);
  }
  std::vector<int> start(ncells + 1, 0);
  for (Index i = 0; i < m; ++i) ++start[cell_of[i] + 1];
  for (long c = 0; c < ncells; ++c) start[c + 1] += start[c];
  std::vector<Index> order(m);
  Eigen::Matrix3Xd spos(3, m);  // positions in sorted order: the inner loop reads them in a row
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Index i = 0; i < m; ++i) {
      const int k = fill[cell_of[i]]++;
      order[k] = i;
      spos.col(k) = pos.col(i);
    }
  }

  // Each pair is seen once, from the point that comes first in cell order: its own cell after
  // it and the 13 cells ahead of it (+x; the row at +y; the three rows at +z). Cells of one row
  // are consecutive in the sorted order, so the five neighbourhoods are five ranges of sorted
  // points, read in a row (the sorted positions are contiguous). The work runs over the sorted
  // points in fixed blocks (threads' results do not depend on their number); the pairs found
  // are then ordered by (i, j) by a counting sort on i.
  const double rc2 = cutoff * cutoff;
  const Index nblocks = (m + kBlock - 1) / kBlock;
  std::vector<std::vector<SitePair>> found(nblocks);
  std::size_t tests = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : tests)
  for (Index b = 0; b < nblocks; ++b) {
    auto& list = found[b];
    const Index end = std::min(m, (b + 1) * kBlock);
    for (Index k = b * kBlock; k < end; ++k) {
      const Index i = order[k];
      const Vec3 p = spos.col(k);
      const auto [cx, cy, cz] = coords[i];
      const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, g.n[0] - 1);
      const auto scan = [&](int k0, int k1) {
        for (int kk = k0; kk < k1; ++kk) {
          ++tests;
          if ((spos.col(kk) - p).squaredNorm() >= rc2) continue;
          const Index j = order[kk];
          if (sites && !sites->interact(i, j)) continue;
          list.push_back(i < j ? SitePair{i, j} : SitePair{j, i});
        }
      };
      scan(static_cast<int>(k) + 1, start[g.cell(x1, cy, cz) + 1]);  // own cell on, and +x
      const auto row = [&](int y, int z) {
        if (y < 0 || y >= g.n[1] || z >= g.n[2]) return;
        scan(start[g.cell(x0, y, z)], start[g.cell(x1, y, z) + 1]);
      };
      row(cy + 1, cz);
      for (int y = cy - 1; y <= cy + 1; ++y) row(y, cz + 1);
    }
  }
  out.stats.distance_tests = tests;

  // Counting sort by i, then each i's partners by j (a handful each).
  std::vector<int> first(m + 1, 0);
  for (const auto& l : found)
    for (const SitePair& q : l) ++first[q[0] + 1];
  for (Index i = 0; i < m; ++i) first[i + 1] += first[i];
  out.pairs.resize(first[m]);
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (const auto& l : found)
      for (const SitePair& q : l) out.pairs[fill[q[0]]++] = q;
  }
#pragma omp parallel for schedule(static, 1024)
  for (Index i = 0; i < m; ++i)
    if (first[i + 1] - first[i] > 1)
      std::sort(out.pairs.begin() + first[i], out.pairs.begin() + first[i + 1],
                [](const SitePair& u, const SitePair& v) { return u[1] < v[1]; });
  return out;
}

}  // namespace crumple
