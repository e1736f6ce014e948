// Element colourings of a mesh (edge_colors.hpp).
#include "sim/model/edge_colors.hpp"

namespace crumple {

PatchColoring color_edges(const Mesh& m) {
  std::vector<std::array<Index, 4>> el(m.num_edges());
  for (Index e = 0; e < m.num_edges(); ++e) el[e] = {m.edges[e][0], m.edges[e][1], 0, 0};
  return color_patches(m.num_nodes(), el, 2);
}

PatchColoring color_triangles(const Mesh& m) {
  std::vector<std::array<Index, 4>> el(m.num_triangles());
  for (Index t = 0; t < m.num_triangles(); ++t)
    el[t] = {m.triangles[t][0], m.triangles[t][1], m.triangles[t][2], 0};
  return color_patches(m.num_nodes(), el, 3);
}

PatchColoring color_hinges(const Mesh& m) {
  std::vector<std::array<Index, 4>> el(m.num_hinges());
  for (Index h = 0; h < m.num_hinges(); ++h) el[h] = m.hinges[h].nodes;
  return color_patches(m.num_nodes(), el, 4);
}

std::array<BlockSlot, 4> pair_slots(const BlockPattern& p, Index i, Index j) {
  return {p.slot(i, i), p.slot(i, j), p.slot(j, i), p.slot(j, j)};
}

}  // namespace crumple
