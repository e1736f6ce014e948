// Benchmark of force and Jacobian assembly (issue: foundation): time per hinge at 12k and 48k
// nodes with 1 and 2 threads, the bending Hessian per triangle vs per hinge
// (docs/MODEL.md §4.5), and the memory of the assembled system per node. BM_Forces times the
// force alone (what an explicit stage evaluates) at 3k, 12k and 48k nodes on 1 and 2 threads,
// and each internal term's share of it.
#include "sim/model/edge_colors.hpp"
#include "sim/model/sheet_model.hpp"
#include "tests/bench/bench_mesh.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <map>
#include <memory>
#include <random>

using namespace crumple;

namespace {

State perturbed(const SheetModel& m, double amp) {
  State s = m.rest_state();
  std::mt19937_64 rng(1);
  std::normal_distribution<double> N(0.0, amp);
  for (Index k = 0; k < s.x.size(); ++k) s.x[k] += N(rng);
  for (Index k = 0; k < s.v.size(); ++k) s.v[k] = N(rng);
  return s;
}

const SheetModel& model(int nodes) {
  static std::map<int, std::unique_ptr<SheetModel>> cache;
  auto& m = cache[nodes];
  if (!m) {
    ModelParams p;
    p.ks = 1.0, p.kb = 1e-3, p.mass = 1.0, p.b_iso = 0.01, p.b_int = 0.1;
    m = std::make_unique<SheetModel>(bench_mesh(nodes), p);
  }
  return *m;
}

void BM_ForceAndJacobians(benchmark::State& st) {
  const int nodes = static_cast<int>(st.range(0));
  omp_set_num_threads(static_cast<int>(st.range(1)));
  const SheetModel& m = model(nodes);
  const State s = perturbed(m, 0.02 * m.mesh().mean_edge_length());
  VecX f;
  Jacobians J;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : st) {
    m.forces(s, f);
    m.jacobians(s, J, false);
    benchmark::DoNotOptimize(J.Hx.valuePtr());
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  st.counters["ns_per_hinge"] = ns / (static_cast<double>(st.iterations()) * m.num_hinges());
  // Memory of the assembled system (Hx and Hv, values + column indices + row pointers).
  const double bytes = 2.0 * (J.Hx.nonZeros() * (sizeof(double) + sizeof(int)) +
                              (J.Hx.rows() + 1) * sizeof(int));
  st.counters["bytes_per_node"] = bytes / m.num_nodes();
  st.counters["nodes"] = m.num_nodes();
}

void BM_Forces(benchmark::State& st) {
  const int nodes = static_cast<int>(st.range(0));
  omp_set_num_threads(static_cast<int>(st.range(1)));
  const SheetModel& m = model(nodes);
  const State s = perturbed(m, 0.02 * m.mesh().mean_edge_length());
  VecX f;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : st) {
    m.forces(s, f);
    benchmark::DoNotOptimize(f.data());
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  st.counters["ns_per_node"] = ns / (static_cast<double>(st.iterations()) * m.num_nodes());
  const PatchColoring hc = color_hinges(m.mesh());
  std::size_t patches = 0;
  for (const auto& c : hc) patches += c.size();
  st.counters["hinge_colours"] = static_cast<double>(hc.size());
  st.counters["hinge_patches"] = static_cast<double>(patches);
  // Each term alone (200 evaluations each), in microseconds per evaluation.
  for (const auto& e : m.terms()) {
    VecX g = VecX::Zero(m.num_dofs());
    const auto a = std::chrono::steady_clock::now();
    constexpr int reps = 200;
    for (int r = 0; r < reps; ++r) e.term->add_force(s, g);
    benchmark::DoNotOptimize(g.data());
    st.counters["us_" + e.term->name()] =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - a).count() /
        reps;
  }
}

void BM_BendingHessian(benchmark::State& st) {
  const int nodes = static_cast<int>(st.range(0));
  omp_set_num_threads(1);
  const SheetModel& m = model(nodes);
  const State s = perturbed(m, 0.02 * m.mesh().mean_edge_length());
  BendingTerm b(m.mesh(), 1e-3,
                st.range(1) ? BendingTerm::Assembly::PerTriangle : BendingTerm::Assembly::PerHinge);
  b.bind(m.pattern());
  Jacobians J;
  J.Hx = m.pattern().zero_matrix();
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : st) {
    J.Hx.coeffs().setZero();
    b.add_jacobians(s, J);
    benchmark::DoNotOptimize(J.Hx.valuePtr());
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  st.SetLabel(st.range(1) ? "per triangle" : "per hinge");
  st.counters["ns_per_hinge"] = ns / (static_cast<double>(st.iterations()) * m.num_hinges());
}

}  // namespace

BENCHMARK(BM_ForceAndJacobians)
    ->ArgsProduct({{12000, 48000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Forces)
    ->ArgsProduct({{3000, 12000, 48000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_BendingHessian)->ArgsProduct({{12000, 48000}, {0, 1}})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
