// Radial confinement benchmark (issue: integrator; paper Fig. 5-6): a 10 cm disk, h_eff
// 0.125 mm by default (--thickness), Y = 1 GPa, an inward force beyond a cutoff radius shrinking
// at 1 cm/s. The sheet is integrated once to t0; every variant (explicit only, hybrid with each
// linear solver) then restarts from that same state and is timed over [t0, t0 + dt].
//   bench_radial [--nodes 3000] [--t0 1 [3 ...]] [--dt 1] [--threads 2] [--mass-scale 1] [--force F]
//                [--thickness 0.125] [--mesh-seed 1] [--contact 1]
//                [--variants all|short|block-jacobi|hybrid|explicit] [--explicit-span S]
//                [--explicit-samples K] [--cg-tol 1e-2] [--cg-tol-max 0.1] [--progress]
//                [--warm-state FILE] [--require-warm] [--save-end FILE]
// With contact (the default) the sheet is self-avoiding as in crumple-sim (sites with sigma =
// max(h_eff, half an edge) and the fold barrier), and the share of the wall time spent in
// contact detection (grid searches) and response (force and Jacobian) is printed with the time
// per step and per site (the contact issue's benchmark). --contact 0 is the phantom sheet: its
// hinges can fold through theta = pi, where the bending energy with a plastic rest curvature
// jumps, and explicit steps then fail (measured at 12000 nodes, t = 1.08 s). `--variants short`
// runs only explicit-only and the hybrid with block Jacobi 18 and with the two-level
// preconditioner (two_level.hpp), `block-jacobi` only explicit-only and the block-Jacobi-18
// hybrid, `hybrid` only the two hybrids, `explicit` only explicit-only.
// `--warm-state FILE` keeps the warm state at the first t0 on disk (with the setup it was
// integrated with), so a second run of the same setup skips the warm-up; a state from before t0
// (an interrupted warm-up leaves the last 5 ms chunk it reached) shortens it. `--save-end FILE`
// keeps the block-Jacobi-18 hybrid's state at the end of the interval: a chain of runs
// (--t0 1 --save-end B; --t0 3 --warm-state B) reaches late intervals at 12000 nodes without
// integrating [0, t0] in one sitting; `--require-warm` makes a warm state that is not at t0 an
// error instead of a reason to warm up (tests/bench/radial_chain.sh chains pieces so).
// --cg-tol / --cg-tol-max set the CG tolerances of the timed hybrid variants (forcing.hpp; the
// warm-up keeps the defaults), and each hybrid variant prints where its wall time went.
// The mass is physical by default, as in the paper: the explicit step is bounded by the node
// period sqrt(m / ks), so explicit-only integration of a full second takes hundreds of thousands
// of steps. --explicit-span S integrates the explicit-only variant over [t0, t0 + S] only and
// prints its wall time scaled to dt (marked "scaled"). That is a fair estimate while the step is
// set by stability rather than by the motion (1000 nodes, [1, 2]: 387 to 638 s scaled from
// tenths of a second against 442 and 517 s measured over the whole second); once the sheet is
// in contact the step size varies with the events and a short span can miss them (time the
// whole interval there: --explicit-span 0). `--explicit-samples K` spreads K such spans evenly over
// the interval, each started from the state the first hybrid variant reached there and timed
// there and then (the hybrid's clock stopped meanwhile), so the scaled figure sees the whole
// interval's stages rather than its first moments, and the machine's conditions of the stretch
// of the hybrid it is compared with (this VM's speed drifts by up to 2x over minutes).
// --thickness sets h_eff (default 0.125 mm; the paper's Fig. 5 sheet is 0.25 mm), --mesh-seed
// draws another mesh of the same sheet (the events, and so the hybrid's explicit stretches,
// differ from mesh to mesh). A mass scale s makes explicit steps sqrt(s) larger and the measured
// accelerations a / a_ref = m a lambda / ks s times larger for the same motion, so the sheet
// rarely looks quasistatic: not the paper's regime.
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
#include <functional>
#include <stdexcept>
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
// `progress`, prints a line per chunk. The interval is advanced in `chunks` equal pieces (0: ten
// with `progress`, else one) by one integrator (its step history carries over; a chunk's end
// only clips one step), and `at_chunk` sees the state at the start of each; the time it takes
// is not part of the wall time returned.
double integrate(const RadialSheet& su, const IntegratorSettings& st, State& s, double t_end,
                 RunStats* out, bool with_contact, double force, bool progress = false,
                 int chunks = 0, const std::function<void(const State&)>& at_chunk = {}) {
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
  if (chunks <= 0) chunks = progress ? 10 : 1;
  const auto since = [](std::chrono::steady_clock::time_point a) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
  };
  double outside = 0;  // in at_chunk
  for (int k = 1; k <= chunks; ++k) {
    if (at_chunk) {
      const auto a = std::chrono::steady_clock::now();
      at_chunk(s);
      outside += since(a);
    }
    integ.advance_to(s, k == chunks ? t_end : t_start + k * (t_end - t_start) / chunks);
    if (!progress) continue;
    const IntegratorSummary c = integ.summary();
    std::printf("    t = %.4g s: %ld steps (%ld explicit, %ld switches, %ld rejected), %.1f s wall "
                "(implicit %.1f, explicit %.1f)\n",
                s.t, c.steps(), c.steps_explicit, c.switches, c.rejections(), since(t0) - outside,
                c.wall_implicit, c.wall_explicit);
  }
  const double wall = since(t0) - outside;
  if (out) {
    out->integ = integ.summary();
    if (contact) out->contact = contact->pairs->stats(), out->sites = contact->pairs->sites().size();
  }
  return wall;
}

// Sums the counts and wall times of explicit-only samples (--explicit-samples).
void add_sample(RunStats& total, const RunStats& one) {
  IntegratorSummary& t = total.integ;
  const IntegratorSummary& o = one.integ;
  t.steps_implicit += o.steps_implicit, t.steps_explicit += o.steps_explicit;
  t.switches += o.switches, t.implicit_attempts += o.implicit_attempts;
  t.newton_iters += o.newton_iters, t.cg_iters += o.cg_iters;
  t.rejected_error += o.rejected_error, t.rejected_newton += o.rejected_newton;
  t.rejected_not_spd += o.rejected_not_spd, t.rejected_other += o.rejected_other;
  t.wall_assembly += o.wall_assembly, t.wall_linear += o.wall_linear;
  t.wall_total += o.wall_total, t.wall_implicit += o.wall_implicit;
  t.wall_explicit += o.wall_explicit, t.wall_before_step += o.wall_before_step;
  total.contact.searches += one.contact.searches;
  total.contact.search_seconds += one.contact.search_seconds;
  total.contact.eval_seconds += one.contact.eval_seconds;
  total.sites = one.sites;
}

/// The command line.
struct Options {
  int nodes = 3000, threads = 2;
  std::vector<double> starts{1.0};
  double dt = 1.0, mass_scale = 1.0, force = 0.0, explicit_span = 0.0;
  double cg_tol = IntegratorSettings{}.cg_tol, cg_tol_max = IntegratorSettings{}.cg_tol_max;
  int samples = 1;
  SheetChoice sheet;
  bool with_contact = true, progress = false, require_warm = false;
  std::string which = "all", warm_path, end_path;
  /// The timed hybrids keep the default CG tolerances (the warm-up's integrator).
  bool default_tolerances() const {
    return cg_tol == IntegratorSettings{}.cg_tol && cg_tol_max == IntegratorSettings{}.cg_tol_max;
  }
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("--nodes", o.nodes, "mesh nodes")->check(CLI::Range(50, 10000000));
  app.add_option("--t0", o.starts, "start(s) of the timed intervals (s), e.g. --t0 1 3; the "
                 "warm-up runs on from one start to the next")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--dt", o.dt, "length of each timed interval (s)")->check(CLI::PositiveNumber);
  app.add_option("--threads", o.threads, "OpenMP threads")->check(CLI::Range(1, 1024));
  app.add_option("--mass-scale", o.mass_scale, "node mass / physical mass")
      ->check(CLI::PositiveNumber);
  add_sheet_options(app, o.sheet);
  app.add_option("--force", o.force, "confining force per node in ks h_eff (0: the stage's "
                 "default)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--contact", o.with_contact, "self-contact (1) or phantom sheet (0)");
  app.add_option("--variants", o.which, "all, short (explicit only, block Jacobi 18 and "
                 "two-level), block-jacobi (explicit only and block Jacobi 18), hybrid (block "
                 "Jacobi 18 and two-level) or explicit (explicit only)")
      ->check(CLI::IsMember({"all", "short", "block-jacobi", "hybrid", "explicit"}));
  app.add_option("--cg-tol", o.cg_tol, "CG relative residual of a step's first Newton iteration "
                 "(timed hybrid variants)")
      ->check(CLI::Range(1e-12, 1.0));
  app.add_option("--cg-tol-max", o.cg_tol_max, "loosest, for later Newton iterations; = "
                 "--cg-tol: a fixed tolerance")
      ->check(CLI::Range(1e-12, 1.0));
  app.add_option("--explicit-span", o.explicit_span,
                 "time the explicit-only variant on [t0, t0 + span] and scale to dt (0: all of dt)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--explicit-samples", o.samples,
                 "time explicit-only over this many spans of --explicit-span spread evenly over "
                 "the interval, each from the state the first hybrid variant reached there and "
                 "timed when it got there, and scale their mean rate to dt")
      ->check(CLI::Range(1, 1000));
  app.add_option("--warm-state", o.warm_path,
                 "HDF5 file of the warm state at the first t0: read if it holds this mesh and "
                 "setup at t0 (the warm-up is skipped) or before (the warm-up goes on from it), "
                 "written after a warm-up");
  app.add_option("--save-end", o.end_path,
                 "HDF5 file for the state at the end of the (last) interval from the block-Jacobi "
                 "18 hybrid at the default tolerances: a later --warm-state FILE --t0 T > that "
                 "time warms up from it");
  app.add_flag("--require-warm", o.require_warm, "fail unless --warm-state holds the state at "
               "the first t0 (never warm up: a chain of runs must not fall back to a warm-up "
               "from rest)");
  app.add_flag("--progress", o.progress, "print a line per tenth of each timed interval too (the "
               "warm-up always does)");
}

/// False (after a message) when the options contradict one another.
bool options_consistent(const Options& o) {
  if (o.cg_tol > o.cg_tol_max) {
    std::fprintf(stderr, "bench_radial: --cg-tol %g exceeds --cg-tol-max %g\n", o.cg_tol,
                 o.cg_tol_max);
    return false;
  }
  if (o.samples > 1 && (o.explicit_span <= 0 || o.which == "hybrid" || o.which == "explicit")) {
    std::fprintf(stderr, "bench_radial: --explicit-samples needs --explicit-span > 0 and both the "
                 "explicit-only and a hybrid variant (--variants all, short or block-jacobi)\n");
    return false;
  }
  return true;
}

struct Variant {
  const char* name;
  const char* solver;
  int block;
  bool explicit_only;
};

/// The variants of --variants, in the order they are timed.
std::vector<Variant> variants_for(const Options& o) {
  std::vector<Variant> variants{{"explicit only (RK4(3))", "cg", 18, true},
                                {"hybrid, CG + block Jacobi 18", "block_jacobi", 18, false},
                                {"hybrid, CG + two-level (18, 32)", "two_level", 18, false}};
  // Sampled explicit-only starts from states of the first hybrid's trajectory and is timed while
  // that hybrid runs; it is reported right after it, so a long run that is stopped during a later
  // variant still has the ratio.
  if (o.which == "hybrid" || o.samples > 1) variants.erase(variants.begin());
  if (o.which == "explicit") variants.resize(1);
  if (o.which == "block-jacobi") variants.pop_back();
  if (o.which == "all")
    for (const Variant& v :
         {Variant{"hybrid, CG + block Jacobi 144", "block_jacobi", 144, false},
          Variant{"hybrid, CG, no preconditioner", "cg", 18, false},
          Variant{"hybrid, CG + incomplete Cholesky", "incomplete_cholesky", 18, false},
          Variant{"hybrid, direct LDLT", "ldlt", 18, false}})
      variants.push_back(v);
  if (o.samples > 1)
    variants.insert(variants.begin() + 1, {"explicit only (RK4(3))", "cg", 18, true});
  return variants;
}

/// Brings `s` to t0: from the warm state file when it holds this setup at t0, else by a warm-up
/// (from the file's earlier state, or from where `s` is). False (after a message) when
/// --require-warm finds no warm state at the first t0.
bool reach_start(const RadialSheet& su, const Options& o, const std::string& setup, double t0,
                 State& s) {
  const bool first = t0 == o.starts.front();
  const bool keep = first && !o.warm_path.empty();
  auto w = keep ? load_warm_state(o.warm_path, su.mesh.num_nodes(), t0, setup, true)
                : std::nullopt;
  if (o.require_warm && first && !(w && w->t == t0)) {
    std::fprintf(stderr, "bench_radial: --require-warm: %s does not hold this setup's state at "
                 "t0 = %g s\n", o.warm_path.empty() ? "(no --warm-state)" : o.warm_path.c_str(),
                 t0);
    return false;
  }
  if (w && w->t < t0) {
    // An earlier state of the same setup (e.g. a previous run's --save-end): warm up from it.
    std::printf("warm state at t = %g s read from %s\n", w->t, o.warm_path.c_str());
    s = std::move(*w);
    w.reset();
  }
  if (w) {
    s = std::move(*w);
    std::printf("warm state at t0 = %g s read from %s\ninterval [%g s, %g s]:\n", t0,
                o.warm_path.c_str(), t0, t0 + o.dt);
    return true;
  }
  std::printf("warm-up (hybrid, block Jacobi 18) from t = %g s to t0 = %g s ...\n", s.t, t0);
  // The warm state file follows the warm-up every 5 ms of simulated time (in at least ten
  // chunks; one integrator throughout): an interrupted warm-up resumes from the last chunk
  // reached (with a fresh integrator there). At 12000 nodes in dense contact a tenth of a
  // warm-up over [2, 3] is more than half an hour of wall time.
  const auto save = [&](const State& x) {
    if (keep && x.t > 0) save_warm_state(o.warm_path, x, su.mesh.num_nodes(), setup);
  };
  const int chunks = std::max(10, static_cast<int>(std::ceil((t0 - s.t) / 0.005)));
  const double warm = integrate(su, settings_for("block_jacobi", 18, false), s, t0, nullptr,
                                o.with_contact, o.force, true, chunks, save);
  if (keep) save_warm_state(o.warm_path, s, su.mesh.num_nodes(), setup);
  std::printf("  (%.1f s wall)\ninterval [%g s, %g s]:\n", warm, t0, t0 + o.dt);
  return true;
}

/// One timed interval [t0, t0 + dt]: every variant from the same start state, and the
/// explicit-only samples (--explicit-samples) taken along the first hybrid.
class Interval {
 public:
  Interval(const RadialSheet& su, const Options& o, const std::string& setup, const State& start,
           double t0)
      : su_(su), o_(o), setup_(setup), start_(start), t0_(t0),
        explicit_run_(o.explicit_span > 0 ? std::min(o.explicit_span, o.dt) : o.dt),
        explicit_st_(settings_for("cg", 18, true, o.cg_tol, o.cg_tol_max)),
        samples_due_(o.samples > 1) {}

  /// Times `v` and prints its row and its breakdown; a variant that fails prints why.
  void time(const Variant& v) {
    RunStats rs;
    const double span = v.explicit_only ? explicit_run_ : o_.dt;
    const bool sampled = v.explicit_only && o_.samples > 1;
    try {
      const double measured = sampled ? from_samples(rs, span) : integrate_variant(v, rs, span);
      const double covered = sampled ? span * double(taken_.size()) : span;
      const double wall = measured * o_.dt / covered;
      if (v.explicit_only) explicit_wall_ = wall;
      else hybrid_walls_.emplace_back(v.name, wall);
      print_row(v, rs, wall, measured, covered, span, sampled);
    } catch (const std::exception& e) {
      std::printf("%-34s failed: %s\n", v.name, e.what());
    }
  }

  /// With --explicit-samples: each hybrid's speed-up against the sampled explicit-only rate.
  void print_speedups() const {
    if (o_.samples > 1 && explicit_wall_ > 0)
      for (const auto& [name, wall] : hybrid_walls_)
        std::printf("speed-up of %s against explicit-only: %.1fx\n", name, explicit_wall_ / wall);
  }

 private:
  // --explicit-samples: explicit-only spans timed from the states the first hybrid reaches,
  // each as soon as it reaches it. This VM's speed drifts by up to 2x over minutes: timed after
  // the hybrid, the samples would see other conditions than the stretch they stand for.
  struct Sample {
    double t_from, t_to, wall;
    RunStats stats;
  };

  /// The sampled explicit-only variant: the samples already taken, summed.
  double from_samples(RunStats& rs, double span) const {
    if (!sample_error_.empty() || taken_.empty())
      throw std::runtime_error(
          (taken_.empty() ? std::string("no sample taken") : sample_error_) + " (after " +
          std::to_string(taken_.size()) + " of " + std::to_string(o_.samples) + " samples)");
    double measured = 0;
    for (const Sample& one : taken_) {
      std::printf("    explicit-only sample [%.4g, %.4g]: %.1f s wall, %ld steps (%.1f s "
                  "scaled to dt)\n", one.t_from, one.t_to, one.wall, one.stats.integ.steps(),
                  one.wall * o_.dt / span);
      measured += one.wall;
      add_sample(rs, one.stats);
    }
    return measured;
  }

  /// An explicit-only span from `x` (a state of the first hybrid), timed now; a failure ends
  /// the sampling, not the hybrid.
  void take_sample(const State& x) {
    if (!sample_error_.empty()) return;
    Sample one{x.t, 0, 0, {}};
    State y = x;
    try {
      one.wall = integrate(su_, explicit_st_, y, x.t + explicit_run_, &one.stats, o_.with_contact,
                           o_.force);
    } catch (const std::exception& e) {
      sample_error_ = "sample from t = " + std::to_string(x.t) + " s: " + e.what();
      return;
    }
    one.t_to = y.t;
    taken_.push_back(std::move(one));
  }

  /// Integrates `v` over [t0, t0 + span] from the start state; the first hybrid takes the
  /// samples along (taken whatever its end) and may leave its end state for a later run.
  double integrate_variant(const Variant& v, RunStats& rs, double span) {
    const IntegratorSettings st =
        settings_for(v.solver, v.block, v.explicit_only, o_.cg_tol, o_.cg_tol_max);
    State w = start_;
    const bool first_hybrid = !v.explicit_only && hybrid_walls_.empty();
    double measured = 0;
    if (!v.explicit_only && samples_due_) {
      samples_due_ = false;
      measured = integrate(su_, st, w, t0_ + span, &rs, o_.with_contact, o_.force, o_.progress,
                           o_.samples, [this](const State& x) { take_sample(x); });
    } else
      measured = integrate(su_, st, w, t0_ + span, &rs, o_.with_contact, o_.force, o_.progress);
    // Block Jacobi 18 with the default tolerances: the warm-up's integrator, so its end state
    // can seed a later run's warm-up.
    if (first_hybrid && !o_.end_path.empty() && v.block == 18 &&
        std::string(v.solver) == "block_jacobi" && o_.default_tolerances()) {
      save_warm_state(o_.end_path, w, su_.mesh.num_nodes(), setup_);
      std::printf("    (state at t = %g s written to %s)\n", w.t, o_.end_path.c_str());
    }
    return measured;
  }

  void print_row(const Variant& v, const RunStats& rs, double wall, double measured,
                 double covered, double span, bool sampled) const {
    const IntegratorSummary& sum = rs.integ;
    std::printf("%-34s %10.1f %8ld %8ld %10.2f %10.1f %8ld", v.name, wall, sum.steps(),
                sum.steps_explicit, sum.mean_newton_per_step(), sum.mean_cg_per_newton(),
                sum.rejections());
    if (!v.explicit_only && explicit_wall_ > 0) std::printf(" %8.1fx", explicit_wall_ / wall);
    if (sampled)
      std::printf("   (scaled from %.1f s wall over %zu spans of %g s, each timed when the "
                  "first hybrid reached its start)", measured, taken_.size(), span);
    else if (span < o_.dt)
      std::printf("   (scaled from %.1f s wall over [%g, %g])", measured, t0_, t0_ + span);
    std::printf("\n");
    // The raw totals, for summing the pieces of a chained run (radial_chain.sh).
    std::printf("    totals: measured %.3f s over %g s, steps %ld, explicit %ld, switches %ld, "
                "implicit attempts %ld, newton %ld, cg %ld, rejected %ld %ld %ld %ld, wall "
                "implicit %.3f linear %.3f explicit %.3f\n",
                measured, covered, sum.steps(), sum.steps_explicit, sum.switches,
                sum.implicit_attempts, sum.newton_iters, sum.cg_iters, sum.rejected_error,
                sum.rejected_newton, sum.rejected_not_spd, sum.rejected_other, sum.wall_implicit,
                sum.wall_linear, sum.wall_explicit);
    if (sum.rejections() > 0)
      std::printf("    rejected attempts: error test %ld, Newton %ld, not SPD %ld, other %ld\n",
                  sum.rejected_error, sum.rejected_newton, sum.rejected_not_spd,
                  sum.rejected_other);
    if (!v.explicit_only)
      std::printf("    wall: implicit %.1f s (linear solves %.1f), explicit %.1f s; forces and "
                  "Jacobians (both modes) %.1f s\n",
                  sum.wall_implicit, sum.wall_linear, sum.wall_explicit, sum.wall_assembly);
    if (o_.with_contact) {
      const ContactStats& c = rs.contact;
      std::printf("    %.3g ms per step; contact: detection %.1f%% (%zu searches, %.3g us per "
                  "site and search, %zu sites), response %.1f%%\n",
                  1e3 * measured / std::max<long>(1, sum.steps()),
                  100 * c.search_seconds / measured, c.searches,
                  c.searches ? 1e6 * c.search_seconds / (double(c.searches) * rs.sites) : 0.0,
                  rs.sites, 100 * c.eval_seconds / measured);
    }
  }

  const RadialSheet& su_;
  const Options& o_;
  const std::string& setup_;
  const State& start_;
  const double t0_, explicit_run_;
  const IntegratorSettings explicit_st_;
  double explicit_wall_ = 0;
  std::vector<Sample> taken_;
  std::string sample_error_;
  bool samples_due_;  // taken along the first hybrid attempted, whatever its end
  std::vector<std::pair<const char*, double>> hybrid_walls_;
};

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines show up at once when piped to a file
  Options o;
  CLI::App app{"bench_radial: radial confinement, explicit-only against the hybrid integrator"};
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  if (!options_consistent(o)) return 2;
  std::sort(o.starts.begin(), o.starts.end());
  omp_set_num_threads(o.threads);
  const RadialSheet su = make_radial_sheet(o.nodes, o.mass_scale, o.sheet);
  State s = SheetModel(su.mesh, su.params).rest_state();
  std::printf("radial confinement, %d nodes (mesh seed %llu), %d threads, h_eff %g mm, mass scale "
              "%g, force %s, %s\n",
              su.mesh.num_nodes(), static_cast<unsigned long long>(o.sheet.mesh_seed),
              omp_get_max_threads(), o.sheet.thickness_mm, o.mass_scale,
              o.force > 0 ? (std::to_string(o.force) + " ks h_eff").c_str() : "the stage's default",
              o.with_contact ? "self-contact" : "phantom sheet");
  const std::vector<Variant> variants = variants_for(o);
  const std::string setup = warm_description(su, o.force, o.with_contact);
  for (const double t0 : o.starts) {
    if (!reach_start(su, o, setup, t0, s)) return 2;
    std::printf("%-34s %10s %8s %8s %10s %10s %8s %9s\n", "variant", "wall [s]", "steps", "expl.",
                "newton/st", "cg/newton", "rejects", "speed-up");
    Interval interval(su, o, setup, s, t0);
    for (const Variant& v : variants) interval.time(v);
    interval.print_speedups();
  }
}
