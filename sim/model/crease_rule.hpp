// Which hinges the run file marks as creases for viewers (docs/FILE_FORMAT.md, the `crease`
// masks): |p| > F c0, with p the plastic rest curvature and c0 the yield curvature. F is the
// analysis's default (analysis/creases/threshold_rule.hpp; docs/STATISTICS.md §5 discusses the
// choice, a convention): the two programs share no code, so a test holds the two equal, and
// what ParaView shows is what the report counts by default.
#pragma once

#include <cmath>
#include <numbers>

namespace crumple {

inline constexpr double kCreaseThresholdFactor = 0.5;

/// The crease threshold on |p|: 2 sin(angle / 2) for a stated crease angle (degrees, > 0;
/// output.crease_angle), else kCreaseThresholdFactor c0. The analysis resolves its default the
/// same way (analysis/run/analyze_run.cpp, resolve_threshold).
inline double crease_threshold(double c0, double crease_angle_deg) {
  return crease_angle_deg > 0 ? 2.0 * std::sin(crease_angle_deg * std::numbers::pi / 360.0)
                              : kCreaseThresholdFactor * c0;
}

}  // namespace crumple
