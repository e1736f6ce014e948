// Why the hybrid integrator stays explicit: where the largest accelerations are along a radial
// confinement run (paper Fig. 5a) and how many nodes carry them.
//
// The hybrid switches back to the quasistatic mode when the moving average of a_max / a_ref
// falls below integrator.switch_down (1e-6; a_ref = ks / (m lambda)). a_max is the largest
// acceleration of any node, so one event anywhere on the sheet holds the whole sheet explicit.
// This program integrates the hybrid (block Jacobi 18) from a warm state of bench_radial and,
// every `interval`, prints the mode, a_max / a_ref, the number of nodes above 1e-6, 1e-4 and
// 1e-2 a_ref, where the fastest node sits (its rest radius over the disk radius, and its distance
// beyond the confining cutoff in h_eff), the kinetic energy, and the active contacts and folds.
//   diag_switching --nodes 12000 --warm-state FILE [--t-end T] [--interval 1e-3] [--explicit]
#include "protocols/integrator_stepper.hpp"
#include "tests/bench/radial_sheet.hpp"
#include "tests/bench/warm_state.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>

using namespace crumple;

int main(int argc, char** argv) {
  int nodes = 12000;
  std::string warm_path;
  double t_end = 0, interval = 1e-3;
  bool start_explicit = false;
  int around = 0;
  IntegratorSettings st;
  st.plastic_c0 = 0.3;
  CLI::App app{"diag_switching: where the hybrid's largest accelerations are"};
  app.add_option("--nodes", nodes, "mesh nodes")->check(CLI::Range(50, 10000000));
  app.add_option("--warm-state", warm_path, "warm state from bench_radial --warm-state/--save-end")
      ->required();
  app.add_option("--t-end", t_end, "end time (s); default the warm state's + 0.02");
  app.add_option("--interval", interval, "time between reports (s)")->check(CLI::PositiveNumber);
  app.add_flag("--explicit", start_explicit, "start in the explicit mode (as after an event)");
  app.add_option("--bdf-order", st.bdf_order, "highest BDF order")->check(CLI::Range(1, 4));
  app.add_option("--max-growth", st.max_growth, "largest ratio of consecutive steps");
  app.add_option("--log-around", around, "at the end, print the step log rows this close to "
                 "each mode switch");
  CLI11_PARSE(app, argc, argv);

  const RadialSheet su = make_radial_sheet(nodes, 1.0);
  auto loaded = load_warm_state(warm_path, su.mesh.num_nodes(), 1e9,
                                warm_description(su, 0.0, true), true);
  if (!loaded) {
    std::fprintf(stderr, "diag_switching: %s holds no warm state of bench_radial's defaults with "
                 "%d nodes\n", warm_path.c_str(), nodes);
    return 2;
  }
  State s = std::move(*loaded);
  if (t_end <= s.t) t_end = s.t + 0.02;

  SheetModel model(su.mesh, su.params);
  std::unique_ptr<SelfContact> contact = add_contact(su, model);
  if (start_explicit) st.mode_initial = IntegrationMode::Explicit;
  Integrator integ(model, st);
  integ.before_step = [&](const State& x) { return contact->update(x.x); };
  const auto stage = begin_radial_stage(su, model, s, 0.0);
  contact->update(s.x);
  model.rebuild_pattern();

  const Index n = model.num_nodes();
  const double lambda = std::sqrt(n / su.mesh.total_area());
  const double a_ref = su.params.ks / (su.params.mass * lambda);
  const double h_eff = su.info.h_eff;
  Vec3 c = Vec3::Zero();
  for (Index i = 0; i < n; ++i) c += su.mesh.ref.col(i);
  c /= double(n);
  double r_disk = 0;
  for (Index i = 0; i < n; ++i) r_disk = std::max(r_disk, (su.mesh.ref.col(i) - c).norm());
  const double cutoff0 = r_disk;  // the stage's default start radius, shrinking at 1 cm/s

  std::printf("%d nodes from t = %g s; a_ref = %.3g m/s^2; mode: fraction of explicit steps\n",
              int(n), s.t, a_ref);
  std::printf("%8s %6s %7s %10s %7s %7s %7s %8s %9s %10s %8s %6s\n", "t", "steps", "expl", "amax/aref",
              ">1e-6", ">1e-4", ">1e-2", "r0/R", "out/heff", "E_kin [J]", "contacts", "folds");
  VecX F;
  long last_steps = 0, last_expl = 0;
  for (double t = s.t + interval; t <= t_end + 1e-12; t += interval) {
    integ.advance_to(s, t);
    const IntegratorSummary sum = integ.summary();
    model.forces(s, F);
    int above6 = 0, above4 = 0, above2 = 0;
    double amax = 0;
    Index worst = 0;
    for (Index i = 0; i < n; ++i) {
      const double a = F.segment<3>(3 * i).norm() / su.params.mass / a_ref;
      above6 += a > 1e-6, above4 += a > 1e-4, above2 += a > 1e-2;
      if (a > amax) amax = a, worst = i;
    }
    const double cutoff = cutoff0 - 0.01 * s.t;
    const double r_now = (node(s.x, worst) - c).norm();
    const long steps = sum.steps() - last_steps, expl = sum.steps_explicit - last_expl;
    last_steps = sum.steps(), last_expl = sum.steps_explicit;
    std::printf("%8.4f %6ld %7.2f %10.3g %7d %7d %7d %8.3f %9.2f %10.3g %8ld %6zu\n", s.t, steps,
                steps ? double(expl) / steps : 0.0, amax, above6, above4, above2,
                (su.mesh.ref.col(worst) - c).norm() / r_disk, (r_now - cutoff) / h_eff,
                model.energies(s).kinetic, long(contact->pairs->num_active(s.x)),
                contact->folds ? contact->folds->active_hinges(s.x).size() : std::size_t(0));
  }
  // The step log around each switch: what the mode change does to a_max / a_ref and E_kin.
  const auto& log = integ.log();
  for (std::size_t k = 1; around > 0 && k < log.size(); ++k) {
    if (log[k].mode == log[k - 1].mode) continue;
    std::printf("switch to %s at t = %.7f s:\n%12s %10s %5s %10s %10s\n",
                log[k].mode ? "explicit" : "implicit", log[k].t, "t", "h", "mode", "a/a_ref",
                "E_kin");
    const std::size_t lo = k > std::size_t(around) ? k - around : 0;
    for (std::size_t j = lo; j < std::min(log.size(), k + around); ++j)
      std::printf("%12.7f %10.3g %5d %10.3g %10.3g\n", log[j].t, log[j].h, log[j].mode,
                  log[j].a_ratio, log[j].e_kinetic);
  }
  return 0;
}
