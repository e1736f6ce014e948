// Self-contact force term (contact_term.hpp; paper eq. 10-12, B.8-B.10).
#include "sim/contact/contact_term.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace crumple {

namespace {

std::uint64_t pair_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

ContactTerm::ContactTerm(const Mesh& mesh, const ContactSettings& settings)
    : mesh_(&mesh), settings_(settings) {
  if (!(settings.sigma > 0.0)) throw std::invalid_argument("ContactTerm: sigma must be positive");
  if (settings.skin < 0.0) throw std::invalid_argument("ContactTerm: skin must be >= 0");
  if (settings_.level < 0)
    settings_.level = auto_refinement(mesh, settings.sigma, nullptr, settings.max_level);
  law_.ks = settings.ks;
  law_.sigma = settings.sigma;
  sites_ = build_contact_sites(mesh, settings_.level);
}

inline Vec3 ContactTerm::separation(const VecX& x, Index p) const {
  const PairStencil& st = stencil_[p];
  // Site by site, as the sites' positions would be: r is a small difference of two points.
  const Vec3 a = st.coef[0] * node(x, st.node[0]) + st.coef[1] * node(x, st.node[1]) +
                 st.coef[2] * node(x, st.node[2]);
  const Vec3 b = st.coef[3] * node(x, st.node[3]) + st.coef[4] * node(x, st.node[4]) +
                 st.coef[5] * node(x, st.node[5]);
  return a + b;
}

void ContactTerm::pair_forces(const VecX& x) const {
  const Index m = static_cast<Index>(cand_.size());
  f1_.resize(m);
  active_.resize(m);
  const double sigma2 = law_.sigma * law_.sigma;
#pragma omp parallel for schedule(static)
  for (Index p = 0; p < m; ++p) {
    const Vec3 r = separation(x, p);
    // The squared distance rejects the pairs outside the range without a square root.
    const bool near = r.squaredNorm() < sigma2;
    f1_[p] = near ? law_.force(r) : Vec3::Zero();
    active_[p] = near;
  }
}

bool ContactTerm::stale(const VecX& x) const {
  if (x_search_.size() != x.size() || settings_.skin <= 0.0) return true;
  // Two sites that may interact have no node in common, and a site moves no more than the
  // farthest-moved of its nodes, so a pair's distance has changed by at most d1 + d2, the two
  // largest node displacements since the search: the list holds every pair now closer than
  // sigma while d1 + d2 <= skin sigma.
  const Index n = static_cast<Index>(x.size() / 3);
  // Keeps the two largest of the values offered in (a, b), a >= b.
  const auto keep_two = [](double d, double& a, double& b) {
    if (d <= b) return;
    b = std::min(d, a);
    a = std::max(d, a);
  };
  double d1 = 0, d2 = 0;  // squared
#pragma omp parallel
  {
    double t1 = 0, t2 = 0;  // this thread's
#pragma omp for schedule(static) nowait
    for (Index i = 0; i < n; ++i)
      keep_two((node(x, i) - node(x_search_, i)).squaredNorm(), t1, t2);
#pragma omp critical
    {
      keep_two(t1, d1, d2);
      keep_two(t2, d1, d2);
    }
  }
  return std::sqrt(d1) + std::sqrt(d2) > settings_.skin * law_.sigma;
}

bool ContactTerm::update(const VecX& x) {
  ++stats_.updates;
  if (!stale(x)) return false;
  const std::vector<SitePair> old = std::move(cand_);
  search(x);
  // Both lists are sorted by (i, j): walk them together for new pairs now in range.
  const double sigma2 = law_.sigma * law_.sigma;
  auto o = old.begin();
  for (const SitePair& q : cand_) {
    while (o != old.end() && *o < q) ++o;
    if (o != old.end() && *o == q) continue;
    if ((pos_.col(q[0]) - pos_.col(q[1])).squaredNorm() < sigma2) return true;
  }
  return false;
}

void ContactTerm::search(const VecX& x) {
  const auto t0 = std::chrono::steady_clock::now();
  sites_.positions(x, pos_);
  ContactPairs found = find_pairs(pos_, law_.sigma * (1.0 + settings_.skin), &sites_);
  cand_ = std::move(found.pairs);
  stats_.last = found.stats;
  x_search_ = x;

  // The pairs' stencils (eq. 11-12): site 1's nodes with +w, site 2's with -w. A real weight is
  // never zero (contact_sites.hpp), so a zero coefficient marks a padded role below.
  const Index m = static_cast<Index>(cand_.size());
  stencil_.resize(m);
#pragma omp parallel for schedule(static)
  for (Index p = 0; p < m; ++p)
    for (int side = 0; side < 2; ++side) {
      const ContactSite& s = sites_.sites[cand_[p][side]];
      const double sign = side == 0 ? 1.0 : -1.0;
      for (int k = 0; k < 3; ++k) {
        stencil_[p].node[3 * side + k] = k < s.count ? s.nodes[k] : s.nodes[0];
        stencil_[p].coef[3 * side + k] = k < s.count ? sign * s.weights[k] : 0.0;
      }
    }

  // Node -> (pair, role) CSR, filled in pair order so that gathers are deterministic.
  const Index n = mesh_->num_nodes();
  std::vector<int> count(n + 1, 0);
  for (const PairStencil& st : stencil_)
    for (int r = 0; r < 6; ++r)
      if (st.coef[r] != 0.0) ++count[st.node[r] + 1];
  rows_.clear();
  row_start_.assign(1, 0);
  std::vector<int> row_of(n, -1);
  for (Index i = 0; i < n; ++i)
    if (count[i + 1] > 0) {
      row_of[i] = static_cast<int>(rows_.size());
      rows_.push_back(i);
      row_start_.push_back(row_start_.back() + count[i + 1]);
    }
  entries_.resize(row_start_.back());
  entry_coef_.resize(row_start_.back());
  std::vector<int> fill(row_start_.begin(), row_start_.end() - 1);
  for (Index p = 0; p < m; ++p)
    for (int r = 0; r < 6; ++r) {
      if (stencil_[p].coef[r] == 0.0) continue;
      const int e = fill[row_of[stencil_[p].node[r]]]++;
      entries_[e] = p;
      entry_coef_[e] = stencil_[p].coef[r];
    }
  cross_stale_ = true;

  ++stats_.searches;
  stats_.search_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void ContactTerm::refresh_cross() const {
  if (!cross_stale_) return;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::uint64_t> cross;
  cross.reserve(9 * stencil_.size());
  for (const PairStencil& st : stencil_)
    for (int a = 0; a < 3; ++a)
      for (int b = 3; b < 6; ++b)
        if (st.coef[a] != 0.0 && st.coef[b] != 0.0)
          cross.push_back(pair_key(st.node[a], st.node[b]));
  std::sort(cross.begin(), cross.end());
  cross.erase(std::unique(cross.begin(), cross.end()), cross.end());
  if (cross != cross_) {
    cross_ = std::move(cross);
    ++version_;
  }
  cross_stale_ = false;
  stats_.search_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::uint64_t ContactTerm::pattern_version() const {
  refresh_cross();
  return version_;
}

Index ContactTerm::num_active(const VecX& x) const {
  const Index m = static_cast<Index>(cand_.size());
  Index active = 0;
#pragma omp parallel for schedule(static) reduction(+ : active)
  for (Index p = 0; p < m; ++p) {
    double rho;
    if (law_.in_range(separation(x, p).norm(), rho)) ++active;
  }
  return active;
}

namespace {
// Adds the wall time of its scope to a counter (evaluations run from serial code).
struct ScopeTimer {
  double& acc;
  double t0 = omp_get_wtime();
  ~ScopeTimer() { acc += omp_get_wtime() - t0; }
};
}  // namespace

double ContactTerm::energy(const State& s) const {
  const ScopeTimer timer{stats_.eval_seconds};
  const Index m = static_cast<Index>(cand_.size());
  const double sigma2 = law_.sigma * law_.sigma;
  double e = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : e)
  for (Index p = 0; p < m; ++p) {
    const double d2 = separation(s.x, p).squaredNorm();
    if (d2 < sigma2) e += law_.energy(std::sqrt(d2));
  }
  return e;
}

void ContactTerm::add_force(const State& s, VecX& f) const {
  const ScopeTimer timer{stats_.eval_seconds};
  pair_forces(s.x);
  const Index nrows = static_cast<Index>(rows_.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (Index k = 0; k < nrows; ++k) {
    Vec3 fa = Vec3::Zero();
    for (int e = row_start_[k]; e < row_start_[k + 1]; ++e) {
      const Index p = entries_[e];
      if (active_[p]) fa += entry_coef_[e] * f1_[p];
    }
    f.segment<3>(3 * rows_[k]) += fa;
  }
}

void ContactTerm::add_jacobians(const State& s, Jacobians& J) const {
  const ScopeTimer timer{stats_.eval_seconds};
  const Index m = static_cast<Index>(cand_.size());
  if (m == 0) return;
  if (!pattern_) throw std::logic_error("ContactTerm::add_jacobians: bind() a pattern first");
  std::vector<Mat3> K(m);
  std::vector<char> active(m);
#pragma omp parallel for schedule(static)
  for (Index p = 0; p < m; ++p) {
    const Vec3 r = separation(s.x, p);
    double rho;
    active[p] = law_.in_range(r.norm(), rho);
    if (active[p]) K[p] = law_.stiffness(r);
  }
  double* val = J.Hx.valuePtr();
  const BlockPattern& pat = *pattern_;
  std::atomic<bool> missing{false};
  const Index nrows = static_cast<Index>(rows_.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (Index k = 0; k < nrows; ++k) {
    const Index a = rows_[k];
    for (int e = row_start_[k]; e < row_start_[k + 1]; ++e) {
      const Index p = entries_[e];
      if (!active[p]) continue;
      const double ca = entry_coef_[e];
      const PairStencil& st = stencil_[p];
      for (int r = 0; r < 6; ++r) {
        if (st.coef[r] == 0.0) continue;  // a padded role
        try {
          add_block(val, pat.slot(a, st.node[r]), (ca * st.coef[r]) * K[p]);
        } catch (const std::out_of_range&) {
          missing = true;
        }
      }
    }
  }
  if (missing)
    throw std::logic_error("ContactTerm::add_jacobians: pattern lacks contact blocks; rebuild it "
                           "after update()");
}

void ContactTerm::coupled_pairs(std::vector<std::pair<Index, Index>>& out) const {
  refresh_cross();
  for (const auto& e : mesh_->edges) out.emplace_back(e[0], e[1]);
  for (std::uint64_t key : cross_)
    out.emplace_back(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu));
}

void ContactTerm::bind(const BlockPattern& pattern) {
  refresh_cross();
  for (std::uint64_t key : cross_)
    if (!pattern.contains(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu)))
      throw std::logic_error("ContactTerm::bind: pattern lacks a contact block");
  pattern_ = &pattern;
}

}  // namespace crumple
