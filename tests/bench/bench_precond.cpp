// Preconditioners on one reduced Newton matrix (paper eq. 35, §3.3): the radial confinement
// sheet at a warm state written by `bench_radial --warm-state FILE`, linearised for a BDF1 step
// of size h. Every preconditioner solves the same A dx = b by CG to the same relative residual,
// so iterations and times compare without the trajectory differences of bench_radial (where
// each solver meets its own sequence of buckling events).
//   bench_precond --nodes 12000 --warm-state FILE --t0 1 [--h 1e-3] [--tol 1e-2] [--repeat 3]
//                 [--thickness 0.125] [--mesh-seed 1]
// (--thickness and --mesh-seed as the bench_radial run that wrote the warm state).
#include "protocols/integrator_stepper.hpp"
#include "sim/integrate/pcg.hpp"
#include "sim/integrate/reduced_newton.hpp"
#include "sim/integrate/two_level.hpp"
#include "tests/bench/radial_sheet.hpp"
#include "tests/bench/warm_state.hpp"

#include <CLI/CLI.hpp>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <omp.h>

#include <algorithm>
#include <cstdio>

using namespace crumple;

namespace {

// Block Jacobi applied through each block's Cholesky factor (two triangular solves), as the
// integrator did before it stored the blocks' inverses (block_jacobi.hpp): the reference for
// what the inverses save per application.
struct BlockJacobiByFactors {
  int bs;
  std::vector<Eigen::LLT<Eigen::MatrixXd>> blocks;
  BlockJacobiByFactors(const SpMat& A, int block) : bs(block) {
    const Eigen::Index n = A.rows();
    blocks.resize((n + bs - 1) / bs);
#pragma omp parallel for schedule(static)
    for (int b = 0; b < int(blocks.size()); ++b) {
      const Eigen::Index start = Eigen::Index(b) * bs, size = std::min<Eigen::Index>(bs, n - start);
      blocks[b].compute(Eigen::MatrixXd(A.block(start, start, size, size)));
    }
  }
  VecX solve(const VecX& r) const {
    VecX z(r.size());
#pragma omp parallel for schedule(static)
    for (int b = 0; b < int(blocks.size()); ++b) {
      const Eigen::Index start = Eigen::Index(b) * bs, size = blocks[b].rows();
      z.segment(start, size) = blocks[b].solve(r.segment(start, size));
    }
    return z;
  }
};

template <class F>
double seconds(F&& f) {
  const double t0 = omp_get_wtime();
  f();
  return omp_get_wtime() - t0;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  int nodes = 3000, threads = 2, repeat = 3;
  double t0 = 1.0, h = 1e-3, tol = 1e-2;
  SheetChoice sheet;
  std::string warm_path;
  CLI::App app{"bench_precond: preconditioned CG on the reduced Newton matrix of a warm state"};
  app.add_option("--nodes", nodes, "mesh nodes")->check(CLI::Range(50, 10000000));
  app.add_option("--warm-state", warm_path, "warm state from bench_radial --warm-state")->required();
  app.add_option("--t0", t0, "time of the warm state (s)");
  app.add_option("--h", h, "BDF1 step (s): A = Hx + Hv / h + plastic term")->check(CLI::PositiveNumber);
  app.add_option("--tol", tol, "CG relative residual")->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  app.add_option("--repeat", repeat, "solves per preconditioner (median time)")->check(CLI::Range(1, 100));
  add_sheet_options(app, sheet);  // as the bench_radial run that wrote the warm state
  CLI11_PARSE(app, argc, argv);
  omp_set_num_threads(threads);
  const RadialSheet su = make_radial_sheet(nodes, 1.0, sheet);
  // The warm state bench_radial writes with its defaults otherwise (stage force, self-contact,
  // physical mass): the setup this program rebuilds.
  auto loaded = load_warm_state(warm_path, su.mesh.num_nodes(), t0,
                                warm_description(su, 0.0, true));
  if (!loaded) {
    std::fprintf(stderr, "bench_precond: %s holds no warm state of bench_radial's defaults with %d "
                 "nodes, h_eff %g mm and mesh seed %llu at t = %g\n", warm_path.c_str(),
                 su.mesh.num_nodes(), sheet.thickness_mm,
                 static_cast<unsigned long long>(sheet.mesh_seed), t0);
    return 2;
  }
  State s = *loaded;
  SheetModel model(su.mesh, su.params);
  std::unique_ptr<SelfContact> contact = add_contact(su, model);
  const auto stage = begin_radial_stage(su, model, s, 0.0);
  contact->update(s.x);
  model.rebuild_pattern();
  PlasticLaw law{0.3, 0.0, 1.0, true};
  ReducedNewton newton(model, law);
  const VecX hx = -s.x + h * s.v;
  const VecX hp = -s.p;
  newton.linearise(s, h, hx, hp);
  const SpMat& A = newton.matrix();
  const VecX& b = newton.rhs();
  std::printf("%d nodes at t = %g s, h = %g s: %ld rows, %ld nonzeros (%.1f per row), tol %g\n",
              su.mesh.num_nodes(), t0, h, long(A.rows()), long(A.nonZeros()),
              double(A.nonZeros()) / A.rows(), tol);
  VecX y(A.rows());
  const VecX xr = VecX::Random(A.rows());
  std::vector<double> tv;
  for (int r = 0; r < 20; ++r) tv.push_back(seconds([&] { y.noalias() = A * xr; }));
  std::sort(tv.begin(), tv.end());
  std::printf("sparse matrix-vector product: %.3f ms\n", 1e3 * tv[tv.size() / 2]);
  std::printf("%-34s %10s %8s %12s %12s\n", "preconditioner", "setup ms", "CG its", "solve ms",
              "ms per it");
  auto run = [&](const char* name, auto make) {
    std::vector<double> setup, solve;
    CgResult res;
    for (int r = 0; r < repeat; ++r) {
      decltype(make()) M;
      setup.push_back(seconds([&] { M = make(); }));
      VecX x;
      solve.push_back(seconds([&] { res = pcg_solve(A, b, x, *M, tol, 5000); }));
    }
    std::sort(setup.begin(), setup.end());
    std::sort(solve.begin(), solve.end());
    const double ss = solve[solve.size() / 2];
    std::printf("%-34s %10.2f %8d %12.1f %12.3f%s\n", name, 1e3 * setup[setup.size() / 2],
                res.iterations, 1e3 * ss, 1e3 * ss / std::max(1, res.iterations),
                res.converged ? "" : (res.indefinite ? "  (not SPD)" : "  (no convergence)"));
  };
  run("none", [] { return std::make_unique<IdentityPrecond>(); });
  for (int bs : {18, 144})
    run(("block Jacobi " + std::to_string(bs) + " by Cholesky factors").c_str(),
        [&] { return std::make_unique<BlockJacobiByFactors>(A, bs); });
  for (int bs : {18, 144})
    run(("block Jacobi " + std::to_string(bs)).c_str(), [&] {
      auto M = std::make_unique<BlockJacobiPreconditioner>(bs);
      M->compute(A);
      return M;
    });
  run("incomplete Cholesky", [&] {
    struct IC {
      std::shared_ptr<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>> ic;
      VecX solve(const VecX& r) const { return ic->solve(r); }
    };
    return std::make_unique<IC>(
        std::make_shared<Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>(SpMatCol(A)));
  });
  for (int agg : {8, 16, 32, 64, 128})
    run(("two-level, block Jacobi 18 + patches of " + std::to_string(agg)).c_str(), [&] {
      auto M = std::make_unique<TwoLevelPreconditioner>(18, agg);
      M->compute(A, s.x);
      return M;
    });
}
