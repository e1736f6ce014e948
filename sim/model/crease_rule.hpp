// Which hinges the run file marks as creases for viewers (docs/FILE_FORMAT.md, the `crease`
// masks): |p| > F c0, with p the plastic rest curvature and c0 the yield curvature. F is the
// analysis's default (analysis/creases/threshold_rule.hpp; docs/STATISTICS.md §5 discusses the
// choice, a convention): the two programs share no code, so a test holds the two equal, and
// what ParaView shows is what the report counts by default.
#pragma once

namespace crumple {

inline constexpr double kCreaseThresholdFactor = 0.5;

}  // namespace crumple
