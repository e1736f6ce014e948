// Quality figures of a triangulated sheet (docs/MODEL.md §9): the numbers reported and tested for
// generated meshes (smallest angle >= 20 degrees, edge-length coefficient of variation <= 0.2),
// and the index locality that the Hilbert renumbering is for (paper Fig. 4).
#pragma once

#include "sim/mesh/mesh.hpp"

namespace crumple {

struct MeshQuality {
  double min_angle_deg = 0.0;  ///< smallest interior angle of any reference triangle
  double mean_edge = 0.0;      ///< mean reference edge length
  double edge_cv = 0.0;        ///< standard deviation / mean of the edge lengths
  double min_area = 0.0;       ///< smallest reference triangle area
  double max_area = 0.0;       ///< largest reference triangle area
  Index nodes = 0, triangles = 0, edges = 0, hinges = 0, boundary_nodes = 0;
};

/// Quality figures of the reference (flat) state of `mesh`.
MeshQuality mesh_quality(const Mesh& mesh);

/// Mean hinge width: over the hinges, the mean of half the sum of the two triangles' altitudes
/// onto the hinge edge, w = (A1 + A2) / |e|. Two flat triangles inscribed in a cylinder of
/// radius R whose axis runs along their common edge meet at the angle w / R (each one's normal
/// points at the middle of its span across the axis), so w turns a physical radius of curvature
/// into a hinge curvature (the yield radius, docs/MODEL.md §7.5). 0 without hinges.
double mean_hinge_width(const Mesh& mesh);

/// Mean |i - j| over the edges (i, j): small when neighbours have nearby indices.
double mean_index_gap(const Mesh& mesh);

}  // namespace crumple
