// Sparsity pattern of 3x3 node blocks, built once per topology and reused by every assembly.
//
// The Jacobians Hx, Hv (3n x 3n) couple nodes that share an element (spring, hinge, contact
// pair). BlockPattern stores which node pairs (i, j) couple, creates a row-major Eigen matrix
// with every coupled 3x3 block present, and hands out a BlockSlot per block so that assembly
// writes straight into valuePtr() without searching. All blocks of row i have the same
// column set, so entry (3i+r, 3j+c) sits at slot.base + r * slot.row_stride + c.
#pragma once

#include "sim/core/types.hpp"

#include <utility>

namespace crumple {

struct BlockSlot {
  int base = -1;        ///< value index of entry (3i, 3j)
  int row_stride = 0;   ///< number of stored entries in each of the rows 3i, 3i+1, 3i+2
};

class BlockPattern {
 public:
  BlockPattern() = default;
  /// n nodes; pairs lists the coupled node pairs (either order, duplicates allowed); the
  /// diagonal blocks (i, i) are always present.
  BlockPattern(Index n, const std::vector<std::pair<Index, Index>>& pairs);

  Index num_nodes() const { return n_; }
  /// An empty (all zero) matrix with the full structure: copy it to get Hx, Hv, ...
  const SpMat& zero_matrix() const { return zero_; }
  /// Slot of block (i, j); throws std::out_of_range if the pair is not in the pattern.
  BlockSlot slot(Index i, Index j) const;
  bool contains(Index i, Index j) const;
  /// Number of stored blocks (each 3x3), counting (i, j) and (j, i) separately.
  std::size_t num_blocks() const { return cols_.size(); }
  /// Block neighbours of node i (sorted, includes i).
  const Index* neighbours_begin(Index i) const { return cols_.data() + row_start_[i]; }
  const Index* neighbours_end(Index i) const { return cols_.data() + row_start_[i + 1]; }

 private:
  Index n_ = 0;
  std::vector<int> row_start_;  // block-row pointers into cols_
  std::vector<Index> cols_;     // sorted block columns per block row
  SpMat zero_;
};

/// Adds the 3x3 block B into the matrix values at a slot (no bounds checks).
inline void add_block(double* values, const BlockSlot& s, const Mat3& B) {
  for (int r = 0; r < 3; ++r) {
    double* row = values + s.base + r * s.row_stride;
    row[0] += B(r, 0);
    row[1] += B(r, 1);
    row[2] += B(r, 2);
  }
}

/// Greedy colouring of elements (each a list of node indices) so that no two elements of one
/// colour share a node. Elements of one colour can then be assembled in parallel without locks,
/// and the summation order into every entry is fixed, so results do not depend on the number
/// of threads. Returns the elements grouped by colour.
std::vector<std::vector<Index>> color_elements(Index num_nodes,
                                               const std::vector<std::array<Index, 4>>& elems,
                                               int nodes_per_elem);

/// Elements grouped for cache-friendly lock-free assembly: colours -> patches -> elements.
/// Nodes are cut into patches of consecutive indices (compact in space on the Hilbert order);
/// each element belongs to the patch of its smallest node; patches whose elements share a node
/// get different colours. One thread handles a whole patch, so its writes stay in cache, and the
/// summation order into every entry (colour by colour, patch order fixed) does not depend on the
/// number of threads.
using PatchColoring = std::vector<std::vector<std::vector<Index>>>;
PatchColoring color_patches(Index num_nodes, const std::vector<std::array<Index, 4>>& elems,
                            int nodes_per_elem, Index patch_size = 96);

}  // namespace crumple
