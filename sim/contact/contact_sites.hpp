// Contact sites: the nodes plus refined points on edges and triangle interiors (paper §2.4,
// Fig. 2), and the rule that keeps neighbouring sites from interacting.
//
// Refinement level L (0..3): on every triangle the sites are the points of the barycentric
// lattice with spacing 1/(L+1), i.e. weights (i, j, k)/(L+1) with i + j + k = L + 1. Level 0 is
// the nodes only; level 1 adds the edge midpoints; level 2 adds two points per edge and one
// interior point; level 3 three per edge and three interior points. Sites along an edge are
// spaced by |e|/(L+1), so with mean edge length l the spacing is l/(L+1); auto_refinement picks
// the smallest L with l/(L+1) <= sigma, so a point of the sheet is never farther than about
// 0.6 sigma from a site and a sheet approaching another meets the repulsion before passing; and
// at least L = 2 while sigma < 0.9 l, because only interior sites (L >= 2) can keep apart two
// triangles one edge apart (their node and edge sites exclude each other, see below).
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
// up to sigma of about 2 l at level 0): a flat or gently curved sheet feels no contact force. Forcing a high level with a large sigma (level 3 with sigma = l) would.
#pragma once

#include "sim/mesh/mesh.hpp"

namespace crumple {

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

/// Builds the sites of all triangles at refinement level 0..3 (throws std::invalid_argument
/// otherwise) with their exclusion sets.
ContactSites build_contact_sites(const Mesh& mesh, int level);

/// Smallest L in 0..3 with mean edge length / (L + 1) <= sigma. If even L = 3 is too coarse, it
/// returns 3 and sets *capped (or, when capped is null, prints a warning on stderr).
int auto_refinement(const Mesh& mesh, double sigma, bool* capped = nullptr);

}  // namespace crumple
