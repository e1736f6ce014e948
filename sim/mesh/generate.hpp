// Random Lloyd-regularised Delaunay meshes of a square or a disk (paper §3.1, docs/MODEL.md §9).
//
// Boundary nodes are placed at the mean node spacing along the outline (square corners
// included) and held fixed; interior points are drawn uniformly from std::mt19937_64(seed),
// relaxed by uniform Lloyd iterations towards a centroidal Voronoi tessellation, and the
// union is Delaunay triangulated. Nodes are then renumbered along a Hilbert curve (paper
// Fig. 4) so that mesh neighbours have nearby indices and the block-Jacobi blocks of the
// solver capture most of the matrix.
//
// Usage (the `mesh` section of a config, docs/CONFIG.md):
//   mesh: { shape: disk, size: 0.1, nodes: 3000, seed: 7 }
#pragma once

#include "sim/mesh/mesh.hpp"

#include <cstdint>
#include <string>

namespace crumple {

struct MeshSpec {
  std::string shape = "square";  ///< "square" or "disk"
  double size = 0.1;             ///< side length or diameter (m in a run: a 10 cm sheet)
  int nodes = 1000;              ///< approximate total number of nodes (>= 10)
  std::uint64_t seed = 1;        ///< seed of the interior points
  int lloyd_iterations = 60;     ///< Lloyd steps (>= 0)
};

/// The valid values of MeshSpec::shape, sorted.
const std::vector<std::string>& mesh_shapes();

/// A flat sheet centred at the origin in the z = 0 plane, triangles counter-clockwise seen from
/// +z, nodes in Hilbert order. The node count is within a few nodes of spec.nodes. The same
/// spec gives a bit-identical mesh. Throws std::invalid_argument on an unknown shape,
/// nodes < 10, size <= 0 (or not finite) or lloyd_iterations < 0.
Mesh generate_mesh(const MeshSpec& spec);

}  // namespace crumple
