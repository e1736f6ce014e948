// Crease extraction from the plastic field (docs/STATISTICS.md §5): a hinge is a crease when |p|
// exceeds a threshold (creases/threshold_rule.hpp says which); the crease length is the total
// rest length of those hinges' edges (the "plastic-edge length" of docs/STATISTICS.md §5).
#pragma once

#include "analysis/io/run_data.hpp"

#include <vector>

namespace crumple::analysis {

/// 1 for each of the h hinges whose |p| > threshold.
std::vector<char> crease_hinges(const std::vector<double>& p, double threshold);

/// Sum of rest_lengths[hinge_edge[i]] over hinges with creased[i] (simulation length units).
double crease_length(const MeshData& mesh, const std::vector<char>& creased);

/// Hinges creased now that were not creased before (both h long); `before` empty means none.
std::vector<char> new_creases(const std::vector<char>& now, const std::vector<char>& before);

}  // namespace crumple::analysis
