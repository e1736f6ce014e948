// Why a quasistatic step is refused: the lowest eigenvalue of the stiffness along a radial
// confinement run (paper Fig. 5a), and what each force term contributes to its mode.
//
// The quasistatic BDF step solves with A = Hx + Hv / (beta h) (+ the plastic term, eq. 35).
// Hv holds b_iso I, so A is SPD for beta h < b_iso / |mu| whenever the conservative stiffness
// Hx has a negative eigenvalue mu: an unstable (buckling) direction of the overdamped flow,
// whose growth rate |mu| / b_iso the step must resolve. This program integrates the hybrid
// scheme and, every `interval`, prints mu (in units of ks), the largest beta h that keeps
// Hx + b_iso / (beta h) I positive definite, and the Rayleigh quotient u^T H_k u / ks of the
// lowest mode u for each term k (springs, bending, contact, the confining force; the quotients
// add up to mu), and nu, the lowest eigenvalue of Hv, in units of b_iso (A tends to Hv / (beta h)
// as h -> 0, so nu < 0 means no step size helps). Dense eigen-decompositions: for a few
// thousand nodes at most.
//   diag_stiffness [nodes=500] [t_end=2] [interval=0.1] [mass_scale=1] [contact=1] [force]
// (force: the confining force per node in units of ks h_eff; default the stage's)
#include "protocols/integrator_stepper.hpp"
#include "tests/bench/radial_sheet.hpp"

#include <Eigen/Eigenvalues>

#include <cstdio>
#include <cstdlib>

using namespace crumple;

int main(int argc, char** argv) {
  const int nodes = argc > 1 ? std::atoi(argv[1]) : 500;
  const double t_end = argc > 2 ? std::atof(argv[2]) : 2.0;
  const double interval = argc > 3 ? std::atof(argv[3]) : 0.1;
  const double mass_scale = argc > 4 ? std::atof(argv[4]) : 1.0;
  const bool with_contact = argc > 5 ? std::atoi(argv[5]) != 0 : true;
  const double force = argc > 6 ? std::atof(argv[6]) : 0.0;
  const RadialSheet su = make_radial_sheet(nodes, mass_scale);
  SheetModel model(su.mesh, su.params);
  std::unique_ptr<SelfContact> contact = with_contact ? add_contact(su, model) : nullptr;
  IntegratorSettings st;
  st.plastic_c0 = 0.3;
  Integrator integ(model, st);
  if (contact) integ.before_step = [&](const State& x) { return contact->update(x.x); };
  State s = model.rest_state();
  const auto stage = begin_radial_stage(su, model, s, force);
  if (contact) contact->update(s.x);
  model.rebuild_pattern();

  const double ks = su.params.ks;
  std::printf("radial confinement, %d nodes, mass scale %g, %s; mu = lowest eigenvalue of Hx / ks\n",
              model.num_nodes(), mass_scale, with_contact ? "self-contact" : "phantom sheet");
  std::printf("%6s %10s %11s %10s %9s %9s %8s  %s\n", "t", "mu/ks", "bh_spd [s]", "nu/b_iso",
              "h_expl", "expl.", "not SPD", "u^T H_k u / ks by term");
  IntegratorSummary before = integ.summary();
  for (double t = interval; t <= t_end + 1e-12; t += interval) {
    integ.advance_to(s, t);
    model.rebuild_pattern();
    Eigen::MatrixXd total = Eigen::MatrixXd::Zero(model.num_dofs(), model.num_dofs());
    std::vector<std::pair<std::string, Eigen::MatrixXd>> parts;
    Eigen::MatrixXd damping = Eigen::MatrixXd::Zero(model.num_dofs(), model.num_dofs());
    for (const auto& e : model.terms()) {
      Jacobians J;
      J.reset(model.pattern());
      e.term->add_jacobians(s, J);
      damping += Eigen::MatrixXd(J.Hv);
      if (!e.term->conservative()) continue;  // drag and internal damping: Hv (above)
      Eigen::MatrixXd H = Eigen::MatrixXd(J.Hx);
      H = 0.5 * (H + H.transpose());
      total += H;
      parts.emplace_back(e.term->name(), std::move(H));
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(total);
    const double mu = eig.eigenvalues()[0];
    const Eigen::VectorXd u = eig.eigenvectors().col(0);
    // Hv alone: the damping matrix that dominates A as h -> 0. Internal damping (eq. 9) has a
    // transverse part b_int (1 - s/l) that is negative on compressed springs; if it outweighs
    // b_iso, no step size makes A positive definite.
    const double nu = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                          0.5 * (damping + damping.transpose()), Eigen::EigenvaluesOnly)
                          .eigenvalues()[0];
    const IntegratorSummary now = integ.summary();
    const double bh_spd = mu < 0 ? su.params.b_iso / -mu : INFINITY;
    const double h_expl = 0.2 * std::sqrt(su.params.mass / ks);
    std::printf("%6.2f %10.3g %11.3g %10.3g %9.2g %9ld %8ld ", t, mu / ks, bh_spd,
                nu / su.params.b_iso, h_expl,
                now.steps_explicit - before.steps_explicit,
                now.rejected_not_spd - before.rejected_not_spd);
    for (const auto& [name, H] : parts) std::printf(" %s %.3g", name.c_str(), u.dot(H * u) / ks);
    std::printf("\n");
    std::fflush(stdout);
    before = now;
  }
}
