// Radial confinement benchmark (issue: integrator; paper Fig. 5-6): a 10 cm disk, h_eff
// 0.125 mm, Y = 1 GPa, an inward force beyond a cutoff radius shrinking at 1 cm/s. The sheet is
// integrated once to t0; every variant (explicit only, hybrid with each linear solver) then
// restarts from that same state and is timed over [t0, t0 + dt].
//   bench_radial [nodes=3000] [t0=1] [dt=1] [threads=2] [mass_scale=1e4] [contact=1] [short]
// With contact=1 (the default) the sheet is self-avoiding as in crumple-sim (sites with sigma =
// max(h_eff, half an edge) and the fold barrier), and the share of the wall time spent in
// contact detection (grid searches) and response (force and Jacobian) is printed with the time
// per step and per site (the contact issue's benchmark). contact=0 is the phantom sheet: its
// hinges can fold through theta = pi, where the bending energy with a plastic rest curvature
// jumps, and explicit steps then fail (measured at 12000 nodes, t = 1.08 s). `short` runs only
// the explicit-only and the default hybrid variants.
// Mass scaling makes explicit steps larger (by its square root) and so changes the comparison:
// the paper's figures are for unscaled mass.
#include "protocols/integrator_stepper.hpp"
#include "tests/bench/radial_sheet.hpp"

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

IntegratorSettings settings_for(const std::string& solver, int block, bool explicit_only) {
  IntegratorSettings st;
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

// Integrates `s` to t_end under the radial confinement stage (begun at t = 0).
double integrate(const RadialSheet& su, const IntegratorSettings& st, State& s, double t_end,
                 RunStats* out, bool with_contact) {
  SheetModel model(su.mesh, su.params);
  std::unique_ptr<SelfContact> contact = with_contact ? add_contact(su, model) : nullptr;
  Integrator integ(model, st);
  if (contact) integ.before_step = [&](const State& x) { return contact->update(x.x); };
  StageContext ctx;
  ctx.model = &model;
  State start = model.rest_state();
  ctx.state = &start;
  ctx.sheet = su.info;
  ctx.t_begin = 0.0;
  const YAML::Node node = YAML::Load("{type: radial_confine, speed: 0.01, duration: 5}");
  auto stage = StageRegistry::builtin().make(node, "bench", "stage");
  stage->begin(ctx);
  if (contact) contact->update(s.x);
  model.rebuild_pattern();
  if (contact) contact->pairs->reset_stats();
  const auto t0 = std::chrono::steady_clock::now();
  integ.advance_to(s, t_end);
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
  const int nodes = argc > 1 ? std::atoi(argv[1]) : 3000;
  const double t0 = argc > 2 ? std::atof(argv[2]) : 1.0;
  const double dt = argc > 3 ? std::atof(argv[3]) : 1.0;
  omp_set_num_threads(argc > 4 ? std::atoi(argv[4]) : 2);
  const double mass_scale = argc > 5 ? std::atof(argv[5]) : 1e4;
  const bool with_contact = argc > 6 ? std::atoi(argv[6]) != 0 : true;
  const bool only_two = argc > 7 && std::string(argv[7]) == "short";
  const RadialSheet su = make_radial_sheet(nodes, mass_scale);
  State s = SheetModel(su.mesh, su.params).rest_state();
  std::printf("radial confinement, %d nodes, %d threads, mass scale %g, %s: reaching t0 = %g s ...\n",
              su.mesh.num_nodes(), omp_get_max_threads(), mass_scale,
              with_contact ? "self-contact" : "phantom sheet", t0);
  const double warm =
      integrate(su, settings_for("block_jacobi", 18, false), s, t0, nullptr, with_contact);
  std::printf("  (%.1f s wall)\n", warm);
  std::printf("%-34s %10s %8s %8s %10s %10s %8s\n", "variant", "wall [s]", "steps", "expl.", "newton/st",
              "cg/newton", "rejects");
  struct Variant {
    const char* name;
    const char* solver;
    int block;
    bool explicit_only;
  };
  std::vector<Variant> variants{{"explicit only (RK4(3))", "cg", 18, true},
                                {"hybrid, CG + block Jacobi 18", "block_jacobi", 18, false}};
  if (!only_two)
    for (const Variant& v : {Variant{"hybrid, CG + block Jacobi 144", "block_jacobi", 144, false},
                             Variant{"hybrid, CG, no preconditioner", "cg", 18, false},
                             Variant{"hybrid, CG + incomplete Cholesky", "incomplete_cholesky", 18, false},
                             Variant{"hybrid, direct LDLT", "ldlt", 18, false}})
      variants.push_back(v);
  for (const Variant& v : variants) {
    State w = s;
    RunStats rs;
    try {
      const double wall = integrate(su, settings_for(v.solver, v.block, v.explicit_only), w,
                                    t0 + dt, &rs, with_contact);
      const IntegratorSummary& sum = rs.integ;
      std::printf("%-34s %10.1f %8ld %8ld %10.2f %10.1f %8ld\n", v.name, wall, sum.steps(),
                  sum.steps_explicit, sum.mean_newton_per_step(), sum.mean_cg_per_newton(),
                  sum.rejections());
      if (with_contact) {
        const ContactStats& c = rs.contact;
        std::printf("    %.3g ms per step; contact: detection %.1f%% (%zu searches, %.3g us per site "
                    "and search, %zu sites), response %.1f%%\n",
                    1e3 * wall / std::max<long>(1, sum.steps()), 100 * c.search_seconds / wall,
                    c.searches,
                    c.searches ? 1e6 * c.search_seconds / (double(c.searches) * rs.sites) : 0.0,
                    rs.sites, 100 * c.eval_seconds / wall);
      }
    } catch (const std::exception& e) {
      std::printf("%-34s failed: %s\n", v.name, e.what());
    }
    std::fflush(stdout);
  }
}
