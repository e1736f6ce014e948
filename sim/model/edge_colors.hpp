// Colourings of the mesh's edges, triangles and hinges for lock-free parallel assembly
// (color_elements in block_pattern.hpp), computed the same way by every term.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/block_pattern.hpp"

namespace crumple {

std::vector<std::vector<Index>> color_edges(const Mesh& mesh);
std::vector<std::vector<Index>> color_triangles(const Mesh& mesh);
std::vector<std::vector<Index>> color_hinges(const Mesh& mesh);

/// Slots of the four blocks (ii, ij, ji, jj) of a two-node element.
std::array<BlockSlot, 4> pair_slots(const BlockPattern& p, Index i, Index j);

/// Runs body(element) over all elements, colour by colour, in parallel within a colour.
template <class Body>
void for_each_colored(const std::vector<std::vector<Index>>& colors, Body&& body) {
  for (const auto& group : colors) {
    const Index m = static_cast<Index>(group.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < m; ++k) body(group[k]);
  }
}

}  // namespace crumple
