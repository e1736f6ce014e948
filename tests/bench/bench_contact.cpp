// Contact cost per site: grid search alone, a full candidate-list refresh (search plus the
// bookkeeping for assembly), and force and Jacobian evaluation, on a sheet folded onto itself
// (half of it in contact, at 0.5 sigma) at about 3k, 12k and 48k sites (level 1).
#include "sim/contact/contact_term.hpp"
#include "tests/contact/sheets.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

using namespace crumple;

namespace {

struct Case {
  Mesh mesh;
  double sigma;
  VecX x;
};

// Grid side for about `sites` level-1 sites (about 4 per node on a grid mesh).
const Case& folded_case(int sites) {
  static std::map<int, Case> cache;
  auto it = cache.find(sites);
  if (it != cache.end()) return it->second;
  const int n = static_cast<int>(std::lround(std::sqrt(sites / 4.0)));
  Case c{testing::grid_mesh(n, n, 1.0, 1.0, 0.2, 1), 0.0, {}};
  c.sigma = 0.5 * c.mesh.mean_edge_length();  // auto refinement: level 1
  c.x = testing::fold_sheet(c.mesh, 0.5, 0.5 * c.sigma);
  return cache.emplace(sites, std::move(c)).first->second;
}

void BM_FindPairs(benchmark::State& st) {
  const Case& c = folded_case(static_cast<int>(st.range(0)));
  const ContactSites sites = build_contact_sites(c.mesh, 1);
  Eigen::Matrix3Xd pos;
  sites.positions(c.x, pos);
  ContactPairs r;
  for (auto _ : st) {
    r = find_pairs(pos, 1.3 * c.sigma, &sites);
    benchmark::DoNotOptimize(r.pairs.data());
  }
  st.SetItemsProcessed(st.iterations() * sites.size());
  st.counters["sites"] = sites.size();
  st.counters["pairs"] = r.pairs.size();
  st.counters["tests/site"] = double(r.stats.distance_tests) / sites.size();
}

void BM_ContactRefresh(benchmark::State& st) {
  const Case& c = folded_case(static_cast<int>(st.range(0)));
  ContactTerm term(c.mesh, {1.0, c.sigma, 1, 0.0});  // skin 0: every update searches
  for (auto _ : st) term.update(c.x);
  st.SetItemsProcessed(st.iterations() * term.sites().size());
  st.counters["candidates"] = term.candidates().size();
}

void BM_ContactForce(benchmark::State& st) {
  const Case& c = folded_case(static_cast<int>(st.range(0)));
  ContactTerm term(c.mesh, {1.0, c.sigma, 1, 0.3});
  term.update(c.x);
  State s{c.x, VecX::Zero(c.x.size()), VecX(), 0.0};
  VecX f = VecX::Zero(c.x.size());
  for (auto _ : st) {
    term.add_force(s, f);
    benchmark::DoNotOptimize(f.data());
  }
  st.SetItemsProcessed(st.iterations() * term.sites().size());
  st.counters["active"] = term.num_active(c.x);
}

void BM_ContactJacobian(benchmark::State& st) {
  const Case& c = folded_case(static_cast<int>(st.range(0)));
  ContactTerm term(c.mesh, {1.0, c.sigma, 1, 0.3});
  term.update(c.x);
  std::vector<std::pair<Index, Index>> pairs;
  term.coupled_pairs(pairs);
  const BlockPattern pattern(c.mesh.num_nodes(), pairs);
  term.bind(pattern);
  State s{c.x, VecX::Zero(c.x.size()), VecX(), 0.0};
  Jacobians J;
  J.reset(pattern);
  for (auto _ : st) {
    term.add_jacobians(s, J);
    benchmark::DoNotOptimize(J.Hx.valuePtr());
  }
  st.SetItemsProcessed(st.iterations() * term.sites().size());
}

}  // namespace

BENCHMARK(BM_FindPairs)->Arg(3000)->Arg(12000)->Arg(48000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactRefresh)->Arg(3000)->Arg(12000)->Arg(48000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactForce)->Arg(3000)->Arg(12000)->Arg(48000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactJacobian)->Arg(3000)->Arg(12000)->Arg(48000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
