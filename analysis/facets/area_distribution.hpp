// Log-binned density of scaled facet areas xi (docs/STATISTICS.md §3.7 step 4): bin edges r^k with
// r = 1.55, density = count / (bin width x total count), so it estimates phi(xi) directly.
#pragma once

#include <vector>

namespace crumple::analysis {

inline constexpr double kAreaBinRatio = 1.55;

struct DensityBin {
  double lo = 0, hi = 0;  ///< bin edges r^k, r^(k+1)
  long count = 0;
  double density = 0;
};

/// Bins from the one holding min(xi) to the one holding max(xi), empty bins included.
/// Values <= 0 are ignored.
std::vector<DensityBin> log_binned_density(const std::vector<double>& xi,
                                           double ratio = kAreaBinRatio);

}  // namespace crumple::analysis
