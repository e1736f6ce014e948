// Human-readable run summary (step_log.hpp).
#include "sim/integrate/step_log.hpp"

#include <cstdio>

namespace crumple {

std::string IntegratorSummary::text() const {
  char buf[768];
  const double other = wall_total - wall_assembly - wall_linear;
  std::snprintf(buf, sizeof buf,
                "steps: %ld implicit, %ld explicit, %ld mode switches\n"
                "newton: %.2f iterations per implicit attempt; cg: %.1f iterations per Newton "
                "iteration\n"
                "rejections: %ld (error test %ld, Newton %ld, not SPD %ld, other %ld)\n"
                "wall time: %.3f s (assembly %.3f, linear solve %.3f, other %.3f)\n"
                "by mode: implicit %.3f s, explicit %.3f s; before-step (contact) %.3f s\n",
                steps_implicit, steps_explicit, switches, mean_newton_per_step(),
                mean_cg_per_newton(), rejections(), rejected_error, rejected_newton,
                rejected_not_spd, rejected_other, wall_total, wall_assembly, wall_linear, other,
                wall_implicit, wall_explicit, wall_before_step);
  return buf;
}

}  // namespace crumple
