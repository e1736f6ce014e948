// Log-binned density; see area_distribution.hpp.
#include "analysis/facets/area_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::analysis {

std::vector<DensityBin> log_binned_density(const std::vector<double>& xi, double ratio) {
  std::vector<double> v;
  for (double x : xi)
    if (x > 0) v.push_back(x);
  if (v.empty()) return {};
  const double lr = std::log(ratio);
  // floor(log_r x) is the bin index; a tiny relative slack keeps exact powers of r in their
  // own bin despite rounding in the logarithm.
  auto index = [&](double x) { return static_cast<long>(std::floor(std::log(x) / lr + 1e-12)); };
  const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
  const long k0 = index(*mn), k1 = index(*mx);
  std::vector<DensityBin> bins(static_cast<std::size_t>(k1 - k0 + 1));
  for (long k = k0; k <= k1; ++k) {
    auto& b = bins[static_cast<std::size_t>(k - k0)];
    b.lo = std::pow(ratio, static_cast<double>(k));
    b.hi = std::pow(ratio, static_cast<double>(k + 1));
  }
  for (double x : v) ++bins[static_cast<std::size_t>(index(x) - k0)].count;
  const double total = static_cast<double>(v.size());
  for (auto& b : bins) b.density = static_cast<double>(b.count) / ((b.hi - b.lo) * total);
  return bins;
}

}  // namespace crumple::analysis
