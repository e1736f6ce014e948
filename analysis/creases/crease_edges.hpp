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

/// Plastic rotation of the hinges (simulation length units x radians): the sum over hinges of
/// the permanent fold angle 2 asin(|p| / 2) times the rest length of the hinge's edge, over
/// the hinges with only[i] when `only` is given. Unlike the crease length it does not depend on
/// how many hinge rows a fold is spread over: a fold of angle A along a line of length L gives
/// A L whether one row of hinges carries it or several carry A / k each, so it measures how much
/// the sheet folded independently of the threshold and of the mesh.
double plastic_rotation(const MeshData& mesh, const std::vector<double>& p,
                        const std::vector<char>* only = nullptr);

/// Hinges creased now that were not creased before (both h long); `before` empty means none.
std::vector<char> new_creases(const std::vector<char>& now, const std::vector<char>& before);

}  // namespace crumple::analysis
