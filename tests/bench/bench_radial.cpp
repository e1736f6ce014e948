// Radial confinement benchmark (issue: integrator; paper Fig. 5-6): a 10 cm disk, h_eff
// 0.125 mm, Y = 1 GPa, an inward force beyond a cutoff radius shrinking at 1 cm/s. The sheet is
// integrated once to t0; every variant (explicit only, hybrid with each linear solver) then
// restarts from that same state and is timed over [t0, t0 + dt].
//   bench_radial [--nodes 3000] [--t0 1 [3 ...]] [--dt 1] [--threads 2] [--mass-scale 1] [--force F]
//                [--contact 1] [--variants all|short|hybrid|explicit] [--explicit-span S]
//                [--cg-tol 1e-2] [--cg-tol-max 0.1] [--progress]
// With contact (the default) the sheet is self-avoiding as in crumple-sim (sites with sigma =
// max(h_eff, half an edge) and the fold barrier), and the share of the wall time spent in
// contact detection (grid searches) and response (force and Jacobian) is printed with the time
// per step and per site (the contact issue's benchmark). --contact 0 is the phantom sheet: its
// hinges can fold through theta = pi, where the bending energy with a plastic rest curvature
// jumps, and explicit steps then fail (measured at 12000 nodes, t = 1.08 s). `--variants short`
// runs only explicit-only and the hybrid with block Jacobi 18 and with the two-level
// preconditioner (two_level.hpp), `hybrid` only the two hybrids, `explicit` only explicit-only.
// `--warm-state FILE` keeps the warm state at the first t0 on disk (with the setup it was
// integrated with), so a second run of the same setup skips the warm-up.
// --cg-tol / --cg-tol-max set the CG tolerances of the timed hybrid variants (forcing.hpp; the
// warm-up keeps the defaults), and each hybrid variant prints where its wall time went.
// The mass is physical by default, as in the paper: the explicit step is bounded by the node
// period sqrt(m / ks), so explicit-only integration of a full second takes hundreds of thousands
// of steps. --explicit-span S integrates the explicit-only variant over [t0, t0 + S] only and
// prints its wall time scaled to dt (marked "scaled"). That is a fair estimate while the step is
// set by stability rather than by the motion (1000 nodes, [1, 2]: 387 to 638 s scaled from
// tenths of a second against 442 and 517 s measured over the whole second); once the sheet is
// in contact the step size varies with the events and a short span can miss them (time the
// whole interval there: --explicit-span 0). A mass scale s makes explicit steps
// sqrt(s) larger and the measured accelerations a / a_ref = m a lambda / ks s times larger for
// the same motion, so the sheet rarely looks quasistatic: not the paper's regime.
#include "protocols/integrator_stepper.hpp"
#include "tests/bench/radial_sheet.hpp"
#include "tests/bench/warm_state.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace crumple;

namespace {

IntegratorSettings settings_for(const std::string& solver, int block, bool explicit_only,
                                double cg_tol = IntegratorSettings{}.cg_tol,
                                double cg_tol_max = IntegratorSettings{}.cg_tol_max) {
  IntegratorSettings st;
  st.cg_tol = cg_tol;
  st.cg_tol_max = cg_tol_max;
  st.plastic_c0 = 0.3;
  st.linear_solver = parse_linear_solver(solver);
  st.block_size = block;
  if (explicit_only) {
    st.mode_initial = IntegrationMode::Explicit;
    st.switch_down = 0.0;  // never back to implicit
  }
  return st;
}

struct RunStats {
  IntegratorSummary integ;
  ContactStats contact;
  std::size_t sites = 0;
};

// Integrates `s` to t_end under the radial confinement stage (begun at t = 0). With
// `progress`, prints a line per tenth of the interval (for the long warm-up).
double integrate(const RadialSheet& su, const IntegratorSettings& st, State& s, double t_end,
                 RunStats* out, bool with_contact, double force, bool progress = false) {
  SheetModel model(su.mesh, su.params);
  std::unique_ptr<SelfContact> contact = with_contact ? add_contact(su, model) : nullptr;
  Integrator integ(model, st);
  if (contact) integ.before_step = [&](const State& x) { return contact->update(x.x); };
  const auto stage = begin_radial_stage(su, model, s, force);
  if (contact) contact->update(s.x);
  model.rebuild_pattern();
  if (contact) contact->pairs->reset_stats();
  const auto t0 = std::chrono::steady_clock::now();
  const double t_start = s.t;
  const int chunks = progress ? 10 : 1;
  for (int k = 1; k <= chunks; ++k) {
    integ.advance_to(s, k == chunks ? t_end : t_start + k * (t_end - t_start) / chunks);
    if (!progress) continue;
    const IntegratorSummary c = integ.summary();
    std::printf("    t = %.4g s: %ld steps (%ld explicit, %ld switches, %ld rejected), %.1f s wall "
                "(implicit %.1f, explicit %.1f)\n",
                s.t, c.steps(), c.steps_explicit, c.switches, c.rejections(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                c.wall_implicit, c.wall_explicit);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (out) {
    out->integ = integ.summary();
    if (contact) out->contact = contact->pairs->stats(), out->sites = contact->pairs->sites().size();
  }
  return wall;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines show up at once when piped to a file
  int nodes = 3000, threads = 2;
  std::vector<double> starts{1.0};
  double dt = 1.0, mass_scale = 1.0, force = 0.0, explicit_span = 0.0;
  double cg_tol = IntegratorSettings{}.cg_tol, cg_tol_max = IntegratorSettings{}.cg_tol_max;
  bool with_contact = true, progress = false;
  std::string which = "all", warm_path;
  CLI::App app{"bench_radial: radial confinement, explicit-only against the hybrid integrator"};
  app.add_option("--nodes", nodes, "mesh nodes")->check(CLI::Range(50, 10000000));
  app.add_option("--t0", starts, "start(s) of the timed intervals (s), e.g. --t0 1 3; the warm-up "
                 "runs on from one start to the next")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--dt", dt, "length of each timed interval (s)")->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  app.add_option("--mass-scale", mass_scale, "node mass / physical mass")->check(CLI::PositiveNumber);
  app.add_option("--force", force, "confining force per node in ks h_eff (0: the stage's default)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--contact", with_contact, "self-contact (1) or phantom sheet (0)");
  app.add_option("--variants", which, "all, short (explicit only, block Jacobi 18 and two-level), "
                 "hybrid (block Jacobi 18 and two-level) or explicit (explicit only)")
      ->check(CLI::IsMember({"all", "short", "hybrid", "explicit"}));
  app.add_option("--cg-tol", cg_tol, "CG relative residual of a step's first Newton iteration "
                 "(timed hybrid variants)")
      ->check(CLI::Range(1e-12, 1.0));
  app.add_option("--cg-tol-max", cg_tol_max, "loosest, for later Newton iterations; = --cg-tol: "
                 "a fixed tolerance")
      ->check(CLI::Range(1e-12, 1.0));
  app.add_option("--explicit-span", explicit_span,
                 "time the explicit-only variant on [t0, t0 + span] and scale to dt (0: all of dt)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--warm-state", warm_path,
                 "HDF5 file of the warm state at the first t0: read if it holds this mesh, time "
                 "and setup (the warm-up is skipped), else written after the warm-up");
  app.add_flag("--progress", progress, "print a line per tenth of each timed interval too (the "
               "warm-up always does)");
  CLI11_PARSE(app, argc, argv);
  if (cg_tol > cg_tol_max) {
    std::fprintf(stderr, "bench_radial: --cg-tol %g exceeds --cg-tol-max %g\n", cg_tol, cg_tol_max);
    return 2;
  }
  std::sort(starts.begin(), starts.end());
  omp_set_num_threads(threads);
  const RadialSheet su = make_radial_sheet(nodes, mass_scale);
  State s = SheetModel(su.mesh, su.params).rest_state();
  std::printf("radial confinement, %d nodes, %d threads, mass scale %g, force %s, %s\n",
              su.mesh.num_nodes(), omp_get_max_threads(), mass_scale,
              force > 0 ? (std::to_string(force) + " ks h_eff").c_str() : "the stage's default",
              with_contact ? "self-contact" : "phantom sheet");
  struct Variant {
    const char* name;
    const char* solver;
    int block;
    bool explicit_only;
  };
  std::vector<Variant> variants{{"explicit only (RK4(3))", "cg", 18, true},
                                {"hybrid, CG + block Jacobi 18", "block_jacobi", 18, false},
                                {"hybrid, CG + two-level (18, 32)", "two_level", 18, false}};
  if (which == "hybrid") variants.erase(variants.begin());
  if (which == "explicit") variants.resize(1);
  if (which == "all")
    for (const Variant& v : {Variant{"hybrid, CG + block Jacobi 144", "block_jacobi", 144, false},
                             Variant{"hybrid, CG, no preconditioner", "cg", 18, false},
                             Variant{"hybrid, CG + incomplete Cholesky", "incomplete_cholesky", 18, false},
                             Variant{"hybrid, direct LDLT", "ldlt", 18, false}})
      variants.push_back(v);
  const std::string setup = warm_description(force, with_contact, mass_scale);
  for (const double t0 : starts) {
    const bool keep = t0 == starts.front() && !warm_path.empty();
    if (auto w = keep ? load_warm_state(warm_path, su.mesh.num_nodes(), t0, setup) : std::nullopt) {
      s = std::move(*w);
      std::printf("warm state at t0 = %g s read from %s\ninterval [%g s, %g s]:\n", t0,
                  warm_path.c_str(), t0, t0 + dt);
    } else {
      std::printf("warm-up (hybrid, block Jacobi 18) from t = %g s to t0 = %g s ...\n", s.t, t0);
      const double warm = integrate(su, settings_for("block_jacobi", 18, false), s, t0, nullptr,
                                    with_contact, force, true);
      if (keep) save_warm_state(warm_path, s, su.mesh.num_nodes(), setup);
      std::printf("  (%.1f s wall)\ninterval [%g s, %g s]:\n", warm, t0, t0 + dt);
    }
    std::printf("%-34s %10s %8s %8s %10s %10s %8s %9s\n", "variant", "wall [s]", "steps", "expl.",
                "newton/st", "cg/newton", "rejects", "speed-up");
    double explicit_wall = 0;
    for (const Variant& v : variants) {
      State w = s;
      RunStats rs;
      const double span = v.explicit_only && explicit_span > 0 ? std::min(explicit_span, dt) : dt;
      try {
        const IntegratorSettings st =
            settings_for(v.solver, v.block, v.explicit_only, cg_tol, cg_tol_max);
        const double measured = integrate(su, st, w, t0 + span, &rs, with_contact, force, progress);
        const double wall = measured * dt / span;
        if (v.explicit_only) explicit_wall = wall;
        const IntegratorSummary& sum = rs.integ;
        std::printf("%-34s %10.1f %8ld %8ld %10.2f %10.1f %8ld", v.name, wall, sum.steps(),
                    sum.steps_explicit, sum.mean_newton_per_step(), sum.mean_cg_per_newton(),
                    sum.rejections());
        if (!v.explicit_only && explicit_wall > 0) std::printf(" %8.1fx", explicit_wall / wall);
        if (span < dt)
          std::printf("   (scaled from %.1f s wall over [%g, %g])", measured, t0, t0 + span);
        std::printf("\n");
        if (sum.rejections() > 0)
          std::printf("    rejected attempts: error test %ld, Newton %ld, not SPD %ld, other %ld\n",
                      sum.rejected_error, sum.rejected_newton, sum.rejected_not_spd,
                      sum.rejected_other);
        if (!v.explicit_only)
          std::printf("    wall: implicit %.1f s (assembly %.1f, linear solves %.1f), explicit %.1f s\n",
                      sum.wall_implicit, sum.wall_assembly, sum.wall_linear, sum.wall_explicit);
        if (with_contact) {
          const ContactStats& c = rs.contact;
          std::printf("    %.3g ms per step; contact: detection %.1f%% (%zu searches, %.3g us per "
                      "site and search, %zu sites), response %.1f%%\n",
                      1e3 * measured / std::max<long>(1, sum.steps()),
                      100 * c.search_seconds / measured, c.searches,
                      c.searches ? 1e6 * c.search_seconds / (double(c.searches) * rs.sites) : 0.0,
                      rs.sites, 100 * c.eval_seconds / measured);
        }
      } catch (const std::exception& e) {
        std::printf("%-34s failed: %s\n", v.name, e.what());
      }
    }
  }
}
