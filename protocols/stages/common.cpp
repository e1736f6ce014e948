// Shared helpers of the built-in stage types (common.hpp).
#include "protocols/stages/common.hpp"

#include "sim/core/schema.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::stages {

std::vector<ParamSpec> common_params(double max_duration, double check_interval) {
  using K = ParamSpec::Kind;
  return {
      {"max_duration", K::Number, schema::format_number(max_duration),
       "cap on the stage's simulated duration (s); the run warns if the target is not reached",
       0.0, 1e30, true},
      // Bounded below: every check ends a chunk of steps, and a vanishing interval is a hang.
      {"check_interval", K::Number, schema::format_number(check_interval),
       "simulated time between checks of the stop condition (s)", 1e-6, 1e30},
  };
}

void apply_common(Stage& stage, const StageArgs& args) {
  stage.max_duration = args.number("max_duration");
  stage.check_interval = args.number("check_interval");
}

double reference_acceleration(const StageContext& ctx) {
  const double lambda = std::sqrt(ctx.model->num_nodes() / ctx.sheet.area);
  return ctx.sheet.ks / (ctx.sheet.mass * lambda);
}

bool quiescent(const StageContext& ctx, double ratio, double speed, double* a_ratio,
               double* speed_sizes) {
  const double a = ctx.max_acceleration() / reference_acceleration(ctx);
  const double v = ctx.max_deformation_speed() / ctx.sheet.size;
  if (a_ratio) *a_ratio = a;
  if (speed_sizes) *speed_sizes = v;
  return a < ratio && v < speed;
}

double foundation_tether_stiffness(const StageContext& ctx, double flatten_length) {
  const double xi = flatten_length * ctx.sheet.size;
  const double kappa = std::sqrt(3.0) / 2.0 * ctx.sheet.kb;
  return kappa * ctx.sheet.area / (static_cast<double>(ctx.model->num_nodes()) * std::pow(xi, 4));
}

Vec3 reference_centroid(const Mesh& mesh) { return mesh.ref.rowwise().mean(); }

double smooth_ramp(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace crumple::stages
