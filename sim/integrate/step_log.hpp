// What the hybrid integrator records: one row per accepted step (docs/MODEL.md §10.9) and a run
// summary (steps per mode, Newton and CG effort, rejections by reason, wall time split).
#pragma once

#include <string>

namespace crumple {

struct LogRow {
  double t = 0;          ///< time at the end of the step
  double h = 0;          ///< step size used
  int mode = 0;          ///< 0 implicit (quasistatic BDF), 1 explicit (RK4)
  int order = 0;         ///< BDF order of the step (4 for explicit RK4)
  int newton_iters = 0;  ///< Newton iterations of the accepted attempt
  int cg_iters = 0;      ///< CG iterations summed over those Newton iterations
  double a_ratio = 0;    ///< a_max / a_ref of the step (before averaging)
  double a_ratio_avg = 0;  ///< its moving average that the switch tests (Fig. 6a)
  int rejections = 0;    ///< rejected attempts before this step was accepted
  double e_stretch = 0, e_bend = 0, e_contact = 0, e_external = 0, e_kinetic = 0;
};

struct IntegratorSummary {
  long steps_implicit = 0, steps_explicit = 0;
  long switches = 0;
  long newton_iters = 0;  ///< over all attempts, accepted or not
  long cg_iters = 0;      ///< over all Newton iterations
  long implicit_attempts = 0;
  long rejected_error = 0, rejected_newton = 0, rejected_not_spd = 0, rejected_other = 0;
  double wall_assembly = 0;  ///< s: forces, Jacobians, reduced system
  double wall_linear = 0;    ///< s: preconditioner and CG / direct solve
  double wall_total = 0;     ///< s inside advance_to
  double wall_implicit = 0;  ///< s in quasistatic (BDF) step attempts
  double wall_explicit = 0;  ///< s in explicit (RK4) step attempts
  double wall_before_step = 0;  ///< s in the before-step callback (contact updates)

  long steps() const { return steps_implicit + steps_explicit; }
  long rejections() const {
    return rejected_error + rejected_newton + rejected_not_spd + rejected_other;
  }
  double mean_newton_per_step() const {
    return implicit_attempts ? double(newton_iters) / implicit_attempts : 0.0;
  }
  double mean_cg_per_newton() const { return newton_iters ? double(cg_iters) / newton_iters : 0.0; }
  /// A few human-readable lines.
  std::string text() const;
};

}  // namespace crumple
