// Colourings of the mesh's edges, triangles and hinges for lock-free parallel assembly
// (color_elements in block_pattern.hpp), computed the same way by every term.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/block_pattern.hpp"

namespace crumple {

PatchColoring color_edges(const Mesh& mesh);
PatchColoring color_triangles(const Mesh& mesh);
PatchColoring color_hinges(const Mesh& mesh);

/// Slots of the four blocks (ii, ij, ji, jj) of a two-node element.
std::array<BlockSlot, 4> pair_slots(const BlockPattern& p, Index i, Index j);

/// Runs body(element) over all elements: colour by colour, the patches of one colour in
/// parallel, the elements of a patch in order on one thread.
template <class Body>
void for_each_colored(const PatchColoring& colors, Body&& body) {
  for (const auto& patches : colors) {
    const Index m = static_cast<Index>(patches.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (Index k = 0; k < m; ++k)
      for (Index e : patches[k]) body(e);
  }
}

}  // namespace crumple
