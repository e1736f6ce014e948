// Counts pairs of non-adjacent triangles (no shared node) of a deformed sheet that intersect,
// with CGAL's exact predicates after a bounding-box sweep. Used to check self-avoidance.
#pragma once

#include "sim/mesh/mesh.hpp"

namespace crumple::testing {

std::size_t count_self_intersections(const Mesh& mesh, const VecX& x);
/// The intersecting pairs themselves (triangle indices, a < b).
std::vector<std::pair<Index, Index>> self_intersections(const Mesh& mesh, const VecX& x);

}  // namespace crumple::testing
