// Helpers shared by the built-in stage types: the parameters every stage accepts, sheet
// geometry in the reference frame, and the quiescence test.
#pragma once

#include "protocols/registry.hpp"

namespace crumple::stages {

/// max_duration and check_interval, accepted by every stage type.
std::vector<ParamSpec> common_params(double max_duration, double check_interval);
void apply_common(Stage& stage, const StageArgs& args);

/// Quiescence as in the integrator's switching test: max|F_i|/m below `ratio` times
/// a_ref = ks/(m lambda), lambda = sqrt(n/A) the linear node density (paper §3.4).
/// Overdamped creep has tiny accelerations at finite speed, so quiescence also asks every node
/// to move slower than `speed` sheet sizes per second relative to the sheet's best-fit rigid
/// motion (a free sheet's slow drift or spin is no change of shape).
/// The two measures are returned through a_ratio and speed_sizes (for the progress line).
bool quiescent(const StageContext& ctx, double ratio, double speed, double* a_ratio = nullptr,
               double* speed_sizes = nullptr);
double reference_acceleration(const StageContext& ctx);

/// Stiffness per node of tethers that act on the sheet together as an elastic foundation of
/// modulus K = k n / A which flattens (or bends) the sheet on length scales above
/// xi = flatten_length x sheet size and barely changes a crease sharper than xi:
/// k = kappa A / (n xi^4), kappa = sqrt(3) kb / 2 (paper eq. 6; docs/MODEL.md §11.3).
double foundation_tether_stiffness(const StageContext& ctx, double flatten_length);

/// Centroid of the reference positions.
Vec3 reference_centroid(const Mesh& mesh);
/// Smooth ramp 0 -> 1 over [0, 1] (C^1: 3s^2 - 2s^3), clamped outside.
double smooth_ramp(double s);

}  // namespace crumple::stages
