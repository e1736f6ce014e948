// Self-contact as a force term (paper §2.4, eq. 10-12; Appendix B.3, B.8-B.10).
//
// The sheet's contact sites (contact_sites.hpp) repel pairwise with the law of
// contact_potential.hpp; each site's force is spread over its triangle's nodes with the
// barycentric weights. The term keeps a candidate list of site pairs closer than
// sigma (1 + skin) at the last search (pair_search.hpp), and evaluates energy, force and
// Jacobian on that list, counting only pairs closer than sigma at the state given. The list is
// valid while the two largest node displacements since the search add up to no more than
// skin sigma: a pair closer than sigma now was then closer than sigma + skin sigma (two sites
// that interact share no node). update(x) re-searches only when that is
// violated, so the candidate list, and with it the Jacobian pattern, changes rarely. The node
// pairs coupled across candidates (the Jacobian pattern's contact blocks) are gathered only when
// a pattern is asked for (pattern_version, coupled_pairs, bind): explicit steps never need them,
// and their sort was half the cost of a search.
//
// Usage: construct, call update(x) before evaluating at x (and again whenever x has moved;
// stale(x) tells whether it must), rebuild the BlockPattern when pattern_version() changed,
// bind(pattern), then energy / add_force / add_jacobians.
//
// Assembly is lock-free and deterministic: per-pair forces and 3x3 blocks are computed in
// parallel, then each node gathers the contributions of its pairs in pair order (a CSR from
// nodes to pair stencils built at each search), so every matrix row and force entry is written
// by one thread, in an order that does not depend on the number of threads.
// Each search also flattens every candidate pair into a stencil of six nodes and signed weights
// (eq. 11-12), so an evaluation reads node positions and weights from one contiguous record per
// pair instead of two site records; a profile of explicit steps in dense contact (3000 nodes,
// level 3) had the site lookups and the pair loop's square root as its top entries. Pairs are
// screened on the squared distance, since most candidates lie outside sigma at any moment.
#pragma once

#include "sim/contact/contact_potential.hpp"
#include "sim/contact/contact_sites.hpp"
#include "sim/contact/pair_search.hpp"
#include "sim/model/force_term.hpp"

#include <array>

namespace crumple {

struct ContactSettings {
  double ks = 1.0;     ///< contact stiffness (eq. 10; the paper uses the spring constant ks)
  double sigma = 0.0;  ///< interaction range (paper: h_eff = sqrt(8 kb / ks)); must be > 0
  int level = -1;      ///< site refinement 0..15; -1 picks auto_refinement(mesh, sigma)
  double skin = 0.5;   ///< candidate-list skin as a fraction of sigma; 0 re-searches every update
  int max_level = 3;   ///< the finest level auto_refinement may pick (after skin: positional
                       ///< initialisers {ks, sigma, level, skin} stay valid)
};

/// Counters for reporting the cost of contact handling.
struct ContactStats {
  std::size_t updates = 0;      ///< calls to update()
  std::size_t searches = 0;     ///< grid searches run
  double search_seconds = 0;    ///< wall time in searches (grid + bookkeeping)
  double eval_seconds = 0;      ///< wall time evaluating energy, force and Jacobian (response)
  SearchStats last;             ///< the last search's grid figures
};

class ContactTerm : public ForceTerm {
 public:
  /// Keeps a reference to mesh (it must outlive the term).
  ContactTerm(const Mesh& mesh, const ContactSettings& settings);

  std::string name() const override { return "contact"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  /// Every mesh edge (blocks within one site) and every node pair across a candidate pair.
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  /// Remembers the pattern (it must stay alive while bound) and checks that it holds all blocks.
  void bind(const BlockPattern& pattern) override;
  /// Changes whenever the set of node pairs coupled across candidate pairs changes.
  std::uint64_t pattern_version() const override;

  /// Refreshes the candidate list for positions x (3n) if needed. Returns true iff the force at
  /// x may differ from the one evaluated with the list before: the new list holds a pair closer
  /// than sigma at x that the old one lacked. (Every pair of the old list in range at x is in
  /// the new one, so no other difference changes the force.)
  bool update(const VecX& x);
  /// True when x is too far from the last search for the candidate list to be trusted.
  bool stale(const VecX& x) const;

  const ContactSettings& settings() const { return settings_; }
  const ContactLaw& law() const { return law_; }
  const ContactSites& sites() const { return sites_; }
  const std::vector<SitePair>& candidates() const { return cand_; }
  /// Candidate pairs closer than sigma at x.
  Index num_active(const VecX& x) const;
  const ContactStats& stats() const { return stats_; }
  void reset_stats() { stats_ = ContactStats{}; }

 private:
  void search(const VecX& x);
  /// Gathers cross_ from the stencils if a search has run since, bumping version_ if it changed.
  void refresh_cross() const;
  /// Candidate pair flattened at the search: roles 0..2 are site 1's nodes with weights +w,
  /// roles 3..5 site 2's with -w; a site with fewer than three nodes repeats its first node
  /// with weight 0, which adds an exact zero.
  struct PairStencil {
    std::array<Index, 6> node;
    std::array<double, 6> coef;
  };
  /// Separation r = x(site 1) - x(site 2) of candidate p, summed site by site. Forced inline:
  /// GCC kept it a call returning through the stack, a fifth of the pair loop's time.
  [[gnu::always_inline]] inline Vec3 separation(const VecX& x, Index p) const;
  /// Fills f1_ with every candidate's force on its site 1 (zero out of range) and active_.
  void pair_forces(const VecX& x) const;

  const Mesh* mesh_;
  ContactSettings settings_;
  ContactLaw law_;
  ContactSites sites_;
  std::vector<SitePair> cand_;
  std::vector<PairStencil> stencil_;   // one per candidate pair
  VecX x_search_;                      // node positions at the last search (empty: none yet)
  std::vector<Index> rows_;            // nodes touched by some candidate pair, ascending
  std::vector<int> row_start_;         // CSR over rows_ into entries_
  std::vector<int> entries_;           // the pair of each (node, role) entry, in pair order
  std::vector<double> entry_coef_;     // the signed weight of each entry's role
  Eigen::Matrix3Xd pos_;               // site positions at the last search
  // Node pairs (a < b) across candidate pairs, sorted; gathered on demand (refresh_cross).
  mutable std::vector<std::uint64_t> cross_;
  mutable bool cross_stale_ = false;
  mutable std::uint64_t version_ = 0;
  const BlockPattern* pattern_ = nullptr;
  mutable ContactStats stats_;  // eval_seconds is accrued in const evaluations
  // Per-pair scratch of the evaluations, kept between calls to spare an allocation of the size
  // of the candidate list per force evaluation (a term is evaluated by one caller at a time).
  mutable std::vector<Vec3> f1_;
  mutable std::vector<char> active_;
};

}  // namespace crumple
