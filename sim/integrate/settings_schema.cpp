// The integrator's keys (settings_schema.hpp). The domains say what the numerics need (the
// yield function divides by 2 - c0, paper eq. 19); the input bounds what a config may ask:
// steps below 1e-12 s do not advance t (of order seconds) by more than its rounding, a hang;
// dense blocks cost memory ~ block_size x dofs; iteration caps beyond them are typos. Tests of
// the method on dimensionless models go below and beyond them in code.
#include "sim/integrate/settings_schema.hpp"

#include "sim/integrate/settings.hpp"

namespace crumple {

namespace {

std::string mode_text(IntegrationMode m) {
  return m == IntegrationMode::Implicit ? "implicit" : "explicit";
}

schema::Section make() {
  using S = IntegratorSettings;
  using namespace schema;
  Section s;
  s.name = "integrator";
  s.meaning = "the hybrid BDF / RK4(3) integrator (paper §3.2-3.4)";
  s.keys = {
      word("mode_initial", &S::mode_initial, {"implicit", "explicit"}, mode_text,
           parse_integration_mode)
          .means("starting formulation: quasistatic BDF or explicit RK4(3)"),
      integer("bdf_order", &S::bdf_order).in(1, 4).means("highest BDF order (start-up climbs from 1)"),
      real("rtol", &S::rtol).above(0).may_change_on_resume()
          .means("relative error tolerance of quasistatic steps (x and p)"),
      real("atol", &S::atol).above(0).units("m").may_change_on_resume()
          .means("absolute error tolerance of both modes (x; v and p in their own units)"),
      real("h_init", &S::h_init).above(0).input_at_least(1e-12).units("s").may_change_on_resume()
          .means("first step"),
      real("h_min", &S::h_min).above(0).input_at_least(1e-12).units("s").may_change_on_resume()
          .means("smallest step: a step that fails there ends the run (exit 3)"),
      real("h_max", &S::h_max).above(0).units("s").may_change_on_resume().means("largest step"),
      real("max_growth", &S::max_growth).above(1).may_change_on_resume()
          .means("largest ratio of consecutive steps (BDF orders 2-4 are held tighter)"),
      real("newton_tol", &S::newton_tol).above(0).may_change_on_resume()
          .means("Newton converged when the weighted RMS of the update is below this"),
      integer("newton_max_iters", &S::newton_max_iters).at_least(1).input_at_most(1000).may_change_on_resume()
          .means("Newton iterations before a step is retried smaller"),
      integer("newton_target", &S::newton_target).at_least(1).input_at_most(1000).may_change_on_resume()
          .means("an accepted step that needed more Newton iterations does not let h grow"),
      word("linear_solver", &S::linear_solver,
           {"two_level", "block_jacobi", "cg", "incomplete_cholesky", "ldlt"}, to_string,
           parse_linear_solver)
          .means("solver of the reduced Newton system (paper eq. 35)"),
      integer("block_size", &S::block_size).at_least(1).input_at_least(3).input_at_most(600)
          .means("scalar rows per block-Jacobi block (block_jacobi, two_level)"),
      integer("coarse_nodes", &S::coarse_nodes).at_least(3).input_at_most(1e9)
          .means("nodes per patch of the two_level coarse space"),
      real("cg_tol", &S::cg_tol).above(0).below(1).may_change_on_resume()
          .means("CG relative residual of a step's first Newton iteration"),
      real("cg_tol_max", &S::cg_tol_max).above(0).below(1).may_change_on_resume()
          .means("loosest CG relative residual of later Newton iterations"),
      integer("cg_max_iters", &S::cg_max_iters).at_least(1).input_at_most(1e9).may_change_on_resume()
          .means("CG iterations per solve at most"),
      real("switch_up", &S::switch_up).above(0)
          .means("moving average of a_max/a_ref above which the integrator turns explicit (§3.4)"),
      real("switch_down", &S::switch_down).at_least(0)
          .means("moving average of a_max/a_ref below which it returns to the quasistatic mode"),
      integer("switch_window", &S::switch_window).at_least(1).input_at_most(1e6)
          .means("accepted steps in the moving average of a_max/a_ref"),
      integer("switch_min_steps", &S::switch_min_steps).at_least(0).input_at_most(1e9)
          .means("accepted steps in a mode before it may switch again"),
      real("explicit_rtol", &S::explicit_rtol).above(0).may_change_on_resume()
          .means("RK4(3) relative tolerance (the absolute one is atol)"),
      real("explicit_h_start", &S::explicit_h_start).above(0).units("sqrt(m/ks)")
          .means("largest first explicit step after a switch, in spring times sqrt(m/ks)"),
      flag("plasticity", &S::plasticity).means("plastic flow of the hinges on or off"),
      real("plastic_c0", &S::plastic_c0).at_least(0).below(2)
          .means("yield curvature c0, per hinge in units of 2 sin(theta/2) (eq. 19); a mesh "
                 "property: material.yield_radius or yield_angle states the sheet's yield instead"),
      real("plastic_gamma", &S::plastic_gamma).at_least(0).means("rate constant gamma (eq. 19)"),
      real("plastic_rate", &S::plastic_rate).above(0).units("1/s")
          .means("time scale of the plastic flow (rate-independent at the default)"),
  };
  // The key named first is the one to blame when the user set it (h_init before h_min: the
  // first step is what a user tunes).
  s.relations = {{"h_min", "<=", "h_max", ""},
                 {"h_min", "<=", "h_init", "h_init"},
                 {"h_init", "<=", "h_max", ""},
                 {"cg_tol", "<=", "cg_tol_max", ""},
                 {"switch_down", "<", "switch_up", ""}};
  return s;
}

}  // namespace

const schema::Section& integrator_schema() {
  static const schema::Section s = make();
  return s;
}

}  // namespace crumple
