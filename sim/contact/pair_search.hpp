// Grid search for pairs of contact sites closer than a cutoff (paper §2.4: a uniform grid over
// the extent of the sites, each site checked against the sites of the neighbouring blocks).
//
// The grid spans the current bounding box of the points with cells of at least the cutoff in
// every direction, so all partners of a point lie in its own and the 26 surrounding cells. Points
// are counting-sorted by cell, and each pair is tested once, from the point first in cell order
// against its own cell and the 13 cells ahead of it. The work runs over the sorted points in
// fixed blocks handed to OpenMP threads, each block writing its own list; the lists are then
// counting-sorted into (i, j) order, so the result (pairs sorted by (i, j), i < j) does not
// depend on the number of threads.
// The number of cells is capped at about four per point (cells grow beyond the cutoff if needed)
// so that a sparse, spread-out configuration does not allocate a huge empty grid.
#pragma once

#include "sim/contact/contact_sites.hpp"

namespace crumple {

using SitePair = std::array<Index, 2>;

struct SearchStats {
  std::array<int, 3> dims{};      ///< grid cells per direction
  double cell = 0;                ///< smallest cell width
  std::size_t distance_tests = 0; ///< distance evaluations (each unordered pair at most once)
};

struct ContactPairs {
  std::vector<SitePair> pairs;  ///< i < j, sorted by (i, j)
  SearchStats stats;
};

/// All pairs (i, j), i < j, of columns of pos (3 x m) with |pos_i - pos_j| < cutoff, without the
/// pairs that `sites` excludes (sites.interact(i, j) false); sites may be null (no exclusion)
/// and must otherwise describe the same m points.
ContactPairs find_pairs(const Eigen::Matrix3Xd& pos, double cutoff,
                        const ContactSites* sites = nullptr);

}  // namespace crumple
