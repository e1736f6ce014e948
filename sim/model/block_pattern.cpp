// Block sparsity pattern and element colouring (block_pattern.hpp).
#include "sim/model/block_pattern.hpp"

#include <algorithm>
#include <stdexcept>

namespace crumple {

BlockPattern::BlockPattern(Index n, const std::vector<std::pair<Index, Index>>& pairs) : n_(n) {
  std::vector<std::vector<Index>> adj(n);
  for (Index i = 0; i < n; ++i) adj[i].push_back(i);
  for (auto [i, j] : pairs) {
    if (i < 0 || j < 0 || i >= n || j >= n) throw std::out_of_range("BlockPattern: node index");
    adj[i].push_back(j);
    adj[j].push_back(i);
  }
  row_start_.assign(n + 1, 0);
  for (Index i = 0; i < n; ++i) {
    auto& a = adj[i];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    row_start_[i + 1] = row_start_[i] + static_cast<int>(a.size());
  }
  cols_.reserve(row_start_[n]);
  for (auto& a : adj) cols_.insert(cols_.end(), a.begin(), a.end());

  // Build the row-major matrix directly in compressed form: row 3i+r holds the three scalar
  // columns of each block neighbour of i, in order.
  const Index dim = 3 * n;
  zero_ = SpMat(dim, dim);
  const std::size_t nnz = 9 * cols_.size();
  zero_.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = zero_.outerIndexPtr();
  int* inner = zero_.innerIndexPtr();
  double* val = zero_.valuePtr();
  int pos = 0;
  for (Index i = 0; i < n; ++i) {
    for (int r = 0; r < 3; ++r) {
      outer[3 * i + r] = pos;
      for (int k = row_start_[i]; k < row_start_[i + 1]; ++k)
        for (int c = 0; c < 3; ++c) {
          inner[pos] = 3 * cols_[k] + c;
          val[pos] = 0.0;
          ++pos;
        }
    }
  }
  outer[dim] = pos;
}

bool BlockPattern::contains(Index i, Index j) const {
  if (i < 0 || i >= n_) return false;
  return std::binary_search(neighbours_begin(i), neighbours_end(i), j);
}

BlockSlot BlockPattern::slot(Index i, Index j) const {
  const Index* b = neighbours_begin(i);
  const Index* e = neighbours_end(i);
  const Index* it = std::lower_bound(b, e, j);
  if (it == e || *it != j) throw std::out_of_range("BlockPattern::slot: block not in pattern");
  const int deg = static_cast<int>(e - b);
  BlockSlot s;
  s.row_stride = 3 * deg;
  s.base = 9 * row_start_[i] + 3 * static_cast<int>(it - b);
  return s;
}

std::vector<std::vector<Index>> color_elements(Index num_nodes,
                                               const std::vector<std::array<Index, 4>>& elems,
                                               int nodes_per_elem) {
  // colour_mask[node] has bit c set when an element of colour c already touches the node;
  // beyond 64 colours we fall back to scanning the groups (never needed for sheet meshes).
  std::vector<std::uint64_t> used(num_nodes, 0);
  std::vector<std::vector<Index>> groups;
  for (Index e = 0; e < static_cast<Index>(elems.size()); ++e) {
    std::uint64_t mask = 0;
    for (int k = 0; k < nodes_per_elem; ++k) mask |= used[elems[e][k]];
    int c = 0;
    while (c < 64 && (mask >> c) & 1ULL) ++c;
    if (c == 64) throw std::runtime_error("color_elements: more than 64 colours needed");
    if (c >= static_cast<int>(groups.size())) groups.resize(c + 1);
    groups[c].push_back(e);
    for (int k = 0; k < nodes_per_elem; ++k) used[elems[e][k]] |= (1ULL << c);
  }
  return groups;
}

PatchColoring color_patches(Index num_nodes, const std::vector<std::array<Index, 4>>& elems,
                            int nodes_per_elem, Index patch_size) {
  const Index num_patches = (num_nodes + patch_size - 1) / patch_size;
  std::vector<std::vector<Index>> members(num_patches);
  std::vector<std::vector<Index>> touching(num_nodes);  // patches whose elements touch a node
  for (Index e = 0; e < static_cast<Index>(elems.size()); ++e) {
    Index lo = elems[e][0];
    for (int k = 1; k < nodes_per_elem; ++k) lo = std::min(lo, elems[e][k]);
    const Index patch = lo / patch_size;
    members[patch].push_back(e);
    for (int k = 0; k < nodes_per_elem; ++k) {
      auto& t = touching[elems[e][k]];
      if (t.empty() || t.back() != patch) t.push_back(patch);
    }
  }
  std::vector<std::vector<Index>> conflicts(num_patches);
  for (auto& t : touching) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    for (std::size_t a = 0; a < t.size(); ++a)
      for (std::size_t b = a + 1; b < t.size(); ++b) {
        conflicts[t[a]].push_back(t[b]);
        conflicts[t[b]].push_back(t[a]);
      }
  }
  std::vector<int> color(num_patches, -1);
  PatchColoring out;
  for (Index p = 0; p < num_patches; ++p) {
    if (members[p].empty()) continue;
    std::vector<char> used(out.size() + 1, 0);
    for (Index q : conflicts[p])
      if (color[q] >= 0) used[color[q]] = 1;
    int c = 0;
    while (used[c]) ++c;
    color[p] = c;
    if (c >= static_cast<int>(out.size())) out.resize(c + 1);
    out[c].push_back(std::move(members[p]));
  }
  return out;
}

}  // namespace crumple
