// The crease threshold and where it comes from (docs/STATISTICS.md §5).
//
// A hinge is a crease when its plastic rest curvature |p| (units c = 2 sin(theta/2)) exceeds a
// threshold. By default the threshold is a fraction F of the run's yield curvature c0
// (integrator.plastic_c0): p flows only while |c - p| > c0 (docs/MODEL.md §7.3, dead band), so
// c0 is the largest bend a hinge takes back elastically, and |p| > F c0 is a permanent set of at
// least F times that, left by a hinge that was bent past (1 + F) c0. With F <= 1 it is also a set
// that a sheet held flat keeps: flattening relaxes |p| above c0 towards c0, never below it
// (docs/MODEL.md §7.3, reverse flow). The value of F is a convention, not a measurement, and the
// crease length depends strongly on it, which the sensitivity table
// (run/threshold_sensitivity.hpp) shows.
#pragma once

#include <array>
#include <string>

namespace crumple::analysis {

/// Default F in threshold = F c0 (crumple-analyze --threshold-c0). The simulator marks crease
/// masks for viewers with the same F (sim/model/crease_rule.hpp; the two programs share no code,
/// a test holds them equal).
inline constexpr double kDefaultThresholdFactor = 0.5;

/// Factors F of the threshold sensitivity table (threshold = F c0).
inline constexpr std::array<double, 6> kSensitivityFactors = {0.25, 0.5, 0.75, 1.0, 1.5, 2.0};

struct ThresholdRule {
  enum class Kind { FractionOfC0, Absolute, CreaseAngle };
  Kind kind = Kind::FractionOfC0;
  double angle_deg = 0.0;                   ///< the crease angle (CreaseAngle only)
  bool angle_from_config = false;           ///< the run's output.crease_angle, not --crease-angle
  double factor = kDefaultThresholdFactor;  ///< F (FractionOfC0 only)
  double c0 = 0.0;                          ///< the run's yield curvature
  bool c0_from_config = false;              ///< false: the simulator's default was assumed
  double threshold = 0.0;                   ///< crease when |p| > threshold
  std::string note;                         ///< one sentence: how the threshold was derived
};

/// threshold = factor x c0; throws std::invalid_argument unless factor > 0 and c0 > 0 (with
/// c0 = 0 every plastic hinge would count, so the rule gives no threshold).
ThresholdRule threshold_from_c0(double factor, double c0, bool c0_from_config);

/// An absolute threshold (> 0, else std::invalid_argument); c0 is kept for the note and the
/// sensitivity table.
ThresholdRule absolute_threshold(double threshold, double c0, bool c0_from_config);

/// A crease angle (degrees, in (0, 180)): threshold = 2 sin(angle / 2), the same on every mesh;
/// else std::invalid_argument. angle_from_config: the run's output.crease_angle stated it (else
/// --crease-angle did).
ThresholdRule threshold_from_crease_angle(double angle_deg, double c0, bool c0_from_config,
                                          bool angle_from_config);

}  // namespace crumple::analysis
