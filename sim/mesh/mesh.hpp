// The triangulated sheet: nodes, triangles, edges with rest lengths, and hinges.
//
// A hinge is an interior edge with its two triangles (paper Fig. 3a, eq. 14-15):
//
//        x2                nodes = {x0, x1, x2, x3}
//       /  \               e0 = x1 - x0 is the shared edge,
//     x0 -- x1             T1 = (x0, x1, x2) and T2 = (x1, x0, x3) are both counter-clockwise
//       \  /               in the reference (flat) state, so n1 = e0 x (x2-x0) and
//        x3                n2 = (x3-x0) x e0 point the same way when the sheet is flat.
//
// rest_factor = sqrt(3)|e0|^2 / (2 (A1 + A2)) is the geometric prefactor of the bending energy
// (15), evaluated once in the reference state (Appendix A: the prefactor is treated as constant).
#pragma once

#include "sim/core/types.hpp"

#include <string>

namespace crumple {

struct Hinge {
  std::array<Index, 4> nodes{};  ///< x0, x1 (shared edge), x2 (opposite in T1), x3 (opposite in T2)
  Index edge = -1;               ///< index into Mesh::edges
  std::array<Index, 2> tris{};   ///< T1, T2
  double rest_factor = 0.0;      ///< sqrt(3)|e0|^2/(2 Abar), dimensionless
};

struct Mesh {
  Eigen::Matrix3Xd ref;                          ///< 3 x n reference positions (z = 0 when flat)
  std::vector<std::array<Index, 3>> triangles;   ///< counter-clockwise seen from +z
  std::vector<std::array<Index, 2>> edges;       ///< (i, j) with i < j
  VecX rest_length;                              ///< per edge, reference length
  std::vector<Hinge> hinges;                     ///< one per interior edge
  std::vector<Index> edge_hinge;                 ///< edge -> hinge index, -1 on the boundary
  std::vector<std::array<Index, 3>> triangle_edges;  ///< edge k of a triangle is opposite vertex k
  std::vector<std::array<Index, 2>> edge_triangles;  ///< the one or two triangles of an edge (-1)
  std::vector<std::uint8_t> boundary;            ///< per node: 1 on the sheet border
  std::string shape;                             ///< "square", "disk" or "custom"

  Index num_nodes() const { return static_cast<Index>(ref.cols()); }
  Index num_triangles() const { return static_cast<Index>(triangles.size()); }
  Index num_edges() const { return static_cast<Index>(edges.size()); }
  Index num_hinges() const { return static_cast<Index>(hinges.size()); }

  /// Reference positions as one flat 3n vector (the initial x of a flat sheet).
  VecX ref_flat() const { return Eigen::Map<const VecX>(ref.data(), ref.size()); }
  double triangle_area(Index t) const;  ///< reference area
  double total_area() const;            ///< reference area of the sheet
  double mean_edge_length() const;
};

/// Builds edges, rest lengths, hinges, boundary flags from reference nodes and triangles.
/// Triangles are reoriented counter-clockwise (seen from +z) if needed. Throws
/// std::invalid_argument on non-manifold input (an edge shared by more than two triangles).
Mesh build_mesh(Eigen::Matrix3Xd ref, std::vector<std::array<Index, 3>> triangles,
                std::string shape = "custom");

/// Renumbers nodes with perm (new index of old node i is perm[i]) and rebuilds the topology.
Mesh renumber_nodes(const Mesh& mesh, const std::vector<Index>& perm);

}  // namespace crumple
