// Contact sites: the nodes plus refined points on edges and triangle interiors (paper §2.4,
// Fig. 2), and the rule that keeps neighbouring sites from interacting.
//
// Refinement level L (0..kMaxContactRefinement): on every triangle the sites are the points of
// the barycentric lattice with spacing 1/(L+1), i.e. weights (i, j, k)/(L+1) with
// i + j + k = L + 1. Level 0 is the nodes only; level 1 adds the edge midpoints; level 2 adds two
// points per edge and one interior point; level 3 three per edge and three interior points;
// level L has L per edge and L(L-1)/2 inside. Sites along an edge are spaced by |e|/(L+1), so
// with mean edge length l the spacing is l/(L+1); auto_refinement picks the smallest L with
// l/(L+1) <= sigma (up to a cap, 3 unless the config raises it), so a point of the sheet is
// never farther than about 0.6 sigma from a site and a sheet approaching another meets the
// repulsion before passing; and at least L = 2 while sigma < 0.9 l, because only interior sites
// (L >= 2) can keep apart two triangles one edge apart (their node and edge sites exclude each
// other, see below).
// Every physical site exists once: node sites first (site s = node s), then the L sites of each
// edge (owned by the edge's first triangle), then the L(L-1)/2 interior sites of each triangle.
//
// Exclusion (paper: sites on the same or adjacent triangles do not interact). T(s) is the set of
// triangles containing site s (the fan of a node, the one or two triangles of an edge, the one
// triangle of an interior site) and N(s) the union of their nodes. Sites s and t interact iff no
// triangle of T(s) shares a node with a triangle of T(t), which is exactly N(s) and N(t) being
// disjoint. On a flat sheet (jittered grid, mean edge l) the closest interacting sites are then
// 2.13 l apart at level 0, 1.27 l at level 1, 0.97 l at level 2 and 0.79 l at level 3, while
// auto_refinement uses level 2 or 3 only for sigma < 0.9 l and level 0 or 1 above (force-free
// up to sigma of about 2 l at level 0): a flat or gently curved sheet feels no contact force.
// Forcing a high level with a large sigma (level 3 with sigma = l) would.
// Finer than the mesh (sigma well below l, the thickness of a sheet meshed coarser than it is
// thick): the spacing rule gives L + 1 >= l/sigma, but the interior site of a triangle nearest
// a corner sits sqrt(3) l/(L+1) from it on an equilateral triangle, so within about 1.7 sigma of
// a corner two triangles one edge apart have no interacting sites. How much that matters in a
// crumpled sheet is measured, not assumed (docs/MODEL.md §6.6).
#pragma once

#include "sim/mesh/mesh.hpp"

namespace crumple {

/// The finest site refinement built: level 15 spaces the sites a sixteenth of an edge apart, about
/// 256 times the sites of level 0; beyond it a finer mesh is the cheaper way to a short range.
inline constexpr int kMaxContactRefinement = 15;

struct ContactSite {
  /// The owning triangle's nodes, reordered so that the nodes with nonzero weight come first.
  std::array<Index, 3> nodes{};
  std::array<double, 3> weights{};  ///< barycentric weights on nodes (sum 1; zero past count)
  int count = 0;                    ///< nonzero weights: 1 node site, 2 edge site, 3 interior
  Index triangle = -1;              ///< owning triangle
};

struct ContactSites {
  int level = 0;
  std::vector<ContactSite> sites;
  std::vector<int> support_start;     ///< CSR offsets (size + 1) into support_nodes
  std::vector<Index> support_nodes;   ///< N(s), sorted, for every site

  Index size() const { return static_cast<Index>(sites.size()); }
  /// True iff sites s and t may interact: N(s) and N(t) are disjoint.
  bool interact(Index s, Index t) const;
  /// Site positions (3 x size) from node positions x (3n, flat).
  void positions(const VecX& x, Eigen::Matrix3Xd& out) const;
};

/// Number of sites at level L: n + L e + L(L-1)/2 t for n nodes, e edges, t triangles.
Index num_contact_sites(const Mesh& mesh, int level);

/// Builds the sites of all triangles at refinement level 0..kMaxContactRefinement (throws
/// std::invalid_argument otherwise) with their exclusion sets.
ContactSites build_contact_sites(const Mesh& mesh, int level);

/// Smallest L with mean edge length / (L + 1) <= sigma, raised to the coarse-mesh floors (2 or
/// 3). If that level is above max_level, it returns max_level and sets *capped (or, when capped
/// is null, prints a warning on stderr). max_level is clamped to 0..kMaxContactRefinement.
int auto_refinement(const Mesh& mesh, double sigma, bool* capped = nullptr, int max_level = 3);

}  // namespace crumple
