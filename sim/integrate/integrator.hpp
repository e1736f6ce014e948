// The hybrid time integrator (paper §3.2-3.4): quasistatic variable-step BDF with the reduced
// Newton solve while the sheet moves slowly, explicit adaptive RK4(3) through fast events, and
// the switch between them.
//
// Quasistatic mode (eq. 22-35): x' = v, 0 = F(x, v, p), p' = g(c(x), p). Each step: Lagrange
// predictor of (x, v, p) through the last points, Newton on the BDF residuals with one SPD
// solve per iteration (reduced_newton.hpp, linear_solver.hpp), local error from corrector minus
// predictor (bdf.hpp), step size control. The order climbs from 1 to bdf_order as accepted
// points accumulate (after the start, a restart or a switch). The error test uses x and p (the
// differential unknowns); v is algebraic.
// Dynamic mode: m v' = F, x' = v, p' = g with RK4 and its embedded third-order estimate
// (rk43.hpp), error weighted over (x, v, p).
// Switching (§3.4, Fig. 6a): a_max = max over nodes of max(|F_i| / m, |v_i(t+h) - v_i(t)| / h)
// (residual and realised acceleration) in quasistatic mode and |F_i| / m in dynamic mode;
// a_ref = ks / (m lambda), lambda = sqrt(n / A). The mean of a_max/a_ref over the last
// switch_window accepted steps above switch_up switches to dynamic, below switch_down back to
// quasistatic, each only after switch_min_steps steps in the current mode.
// Failures (matrix not SPD, Newton not converging, non-finite values) reject the step and retry
// with h / 4; an error-test failure shrinks h by the controller. A quasistatic step that fails
// where h / 4 would be shorter than the first explicit step (explicit_h_start sqrt(m / ks)) is
// retried in the dynamic mode instead, which needs no SPD matrix (a switch that does not wait
// for switch_min_steps). A retry below h_min is made at h_min; a step failing there throws a
// NumericalFailure with the time, h, the reason and the node with the largest residual force.
#pragma once

#include "sim/integrate/linear_solver.hpp"
#include "sim/integrate/plasticity.hpp"
#include "sim/integrate/reduced_newton.hpp"
#include "sim/integrate/settings.hpp"
#include "sim/integrate/step_log.hpp"
#include "sim/model/sheet_model.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace crumple {

/// Everything the integrator carries from step to step, so a checkpoint can store it and a
/// resumed run continues exactly as the uninterrupted one (bit for bit with one thread).
struct IntegratorHistory {
  std::vector<double> times;   ///< accepted times, newest first (times[0] = state's t)
  std::vector<VecX> xs, vs, ps;  ///< the matching x, v, p
  double h = 0;                ///< next step size to try
  IntegrationMode mode = IntegrationMode::Implicit;
  int steps_in_mode = 0;
  std::vector<double> a_window;  ///< last a_max/a_ref values, oldest first
  VecX fsal;                   ///< explicit mode: derivative at the newest point (empty if none)
  double err_prev = 0;         ///< explicit mode: error norm of the last accepted step (0: none)
  IntegratorSummary counters;
};

class Integrator {
 public:
  Integrator(SheetModel& model, const IntegratorSettings& settings);
  ~Integrator();

  /// Integrates s from s.t to t_end (the last step lands exactly on t_end). If s differs from
  /// the newest history point (first call, or the caller changed the state), the multistep
  /// history restarts from s. Throws NumericalFailure.
  void advance_to(State& s, double t_end);

  const std::vector<LogRow>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  IntegratorSummary summary() const { return hist_.counters; }

  const IntegratorHistory& history() const { return hist_; }
  void restore(const IntegratorHistory& h) { hist_ = h; }

  IntegrationMode mode() const { return hist_.mode; }
  double a_ref() const { return a_ref_; }
  const IntegratorSettings& settings() const { return settings_; }

  /// Called before every step attempt with the current state (contact updates). Returns
  /// true if the force at that state may have changed (a contact re-search), which drops the
  /// explicit mode's reused first stage (FSAL).
  std::function<bool(const State&)> before_step;

 private:
  struct Attempt {
    bool ok = false;          ///< solved (error test still to do)
    double err = 0;           ///< weighted RMS local error estimate
    int order = 1;
    int newton_iters = 0, cg_iters = 0;
    double a_ratio = 0;
    std::string failure;      ///< reason when !ok
    bool not_spd = false, newton_failed = false;
    Index worst_node = -1;    ///< largest residual force
    State next;
    VecX fsal;
  };

  void sync_history(const State& s);
  void reset_history(const State& s);
  void push_history(const State& s);
  void implicit_attempt(const State& s, double h, Attempt& a);
  // The parts of implicit_attempt (implicit_step.cpp).
  /// Predictor of the step into `it`; returns the factor turning corrector - predictor into
  /// the local error. `tc`: the step's time points (t + h, then the history's).
  double implicit_predict(const State& s, double h, int ord, std::vector<double> tc, State& it);
  /// Newton from the predictor in a.next; false with a.failure set when it fails.
  bool implicit_newton(double bh, const VecX& hx, const VecX& hp, Attempt& a);
  /// max(|F_i| / m, |v_i(t+h) - v_i(t)| / h) / a_ref at the converged step.
  double realised_acceleration_ratio(const State& s, const State& it, double h) const;
  void explicit_attempt(const State& s, double h, Attempt& a);
  void explicit_rhs(double t, const VecX& y, VecX& dy, State& scratch);
  double plastic_rate_at(const VecX& x, const VecX& p, VecX& g) const;
  /// The same from the hinge curvatures c of that state.
  double plastic_rate_from(const VecX& c, const VecX& p, VecX& g) const;
  /// Each force term's name and force at s, evaluated alone: the diagnostics of a failed step.
  std::vector<std::pair<std::string, VecX>> forces_by_term(const State& s) const;
  /// Each force term's force on `node` at s, largest first ("contact 3.1e+04 N, springs 12 N"):
  /// the diagnostic of a run that fails, naming which physics holds the step down.
  std::string forces_on_node(const State& s, Index node) const;
  void after_accept(const State& s, const Attempt& a, double h, int rejections);
  // The steps of advance_to, in order (integrator.cpp).
  void prepare_attempt(const State& s, bool implicit);
  double plan_step(const State& s, double t_end, bool implicit, int rejections, double proposal,
                   double wall0);
  void attempt(const State& s, double h, bool implicit, Attempt& a);
  void grow_after_accept(const Attempt& a, double h, double proposal, bool implicit,
                         int rejections);
  /// After a failed attempt: the step size of the retry (or a hand-over to the explicit mode);
  /// throws NumericalFailure when a step at h_min fails.
  void retry_after_rejection(const State& s, const Attempt& a, double h, bool implicit,
                             double wall0);
  /// The largest ratio of a step over the one before, for a step with `points` history points.
  double ratio_limit(bool implicit, std::size_t points) const;
  /// explicit_h_start sqrt(m / ks): the first explicit step after a switch.
  double explicit_start_step() const {
    return settings_.explicit_h_start * std::sqrt(model_.params().mass / model_.params().ks);
  }

  SheetModel& model_;
  IntegratorSettings settings_;
  PlasticLaw law_;
  std::unique_ptr<ReducedNewton> newton_;
  LinearSolver solver_;
  double a_ref_ = 1;
  IntegratorHistory hist_;
  std::vector<LogRow> log_;
};

}  // namespace crumple
