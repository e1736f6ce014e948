// Crease extraction from the plastic field (DESIGN.md §8, statistics.md §5): a hinge is a crease
// when |p| exceeds a threshold; the crease length is the total rest length of those hinges'
// edges (the "plastic-edge length" of statistics.md §5).
#pragma once

#include "analysis/io/run_data.hpp"

#include <vector>

namespace crumple::analysis {

/// Default threshold on |p| in curvature units c = 2 sin(theta/2): 0.05 is a rest fold of about
/// 2.9 degrees, well above the numerical noise of p on a flat sheet and well below a real fold
/// (c about 1.4 for a 90 degree fold), so the length depends little on the exact value.
inline constexpr double kDefaultCreaseThreshold = 0.05;

/// 1 for each of the h hinges whose |p| > threshold.
std::vector<char> crease_hinges(const std::vector<double>& p, double threshold);

/// Sum of rest_lengths[hinge_edge[i]] over hinges with creased[i] (simulation length units).
double crease_length(const MeshData& mesh, const std::vector<char>& creased);

/// Hinges creased now that were not creased before (both h long); `before` empty means none.
std::vector<char> new_creases(const std::vector<char>& now, const std::vector<char>& before);

}  // namespace crumple::analysis
