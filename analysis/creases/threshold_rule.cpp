// Crease threshold rules; see threshold_rule.hpp.
#include "analysis/creases/threshold_rule.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace crumple::analysis {
namespace {

std::string c0_source(const ThresholdRule& r) {
  std::ostringstream s;
  s << "c0 = " << r.c0
    << (r.c0_from_config ? " from integrator.plastic_c0 of the run's /config"
                         : ", the simulator's default (the run's /config gives none)");
  return s.str();
}

}  // namespace

ThresholdRule threshold_from_c0(double factor, double c0, bool c0_from_config) {
  if (!(factor > 0)) throw std::invalid_argument("the threshold factor of c0 must be positive");
  if (!(c0 > 0)) {
    std::ostringstream m;
    m << "the yield curvature c0 is " << c0
      << ", so a fraction of it gives no crease threshold; give --threshold P instead";
    throw std::invalid_argument(m.str());
  }
  ThresholdRule r;
  r.kind = ThresholdRule::Kind::FractionOfC0;
  r.factor = factor;
  r.c0 = c0;
  r.c0_from_config = c0_from_config;
  r.threshold = factor * c0;
  std::ostringstream s;
  s << "crease when |p| > " << factor << " c0 = " << r.threshold << " with " << c0_source(r)
    << ": a permanent set of at least " << factor
    << " times the largest bend a hinge takes back elastically (p flows only while "
       "|c - p| > c0); the factor is a convention and the crease length depends strongly on it "
       "(see threshold_sensitivity)";
  r.note = s.str();
  return r;
}

ThresholdRule absolute_threshold(double threshold, double c0, bool c0_from_config) {
  if (!(threshold > 0)) throw std::invalid_argument("the crease threshold must be positive");
  ThresholdRule r;
  r.kind = ThresholdRule::Kind::Absolute;
  r.factor = c0 > 0 ? threshold / c0 : 0.0;
  r.c0 = c0;
  r.c0_from_config = c0_from_config;
  r.threshold = threshold;
  std::ostringstream s;
  s << "crease when |p| > " << threshold << ", an absolute value given with --threshold";
  if (c0 > 0) s << " (that is " << r.factor << " c0, " << c0_source(r) << ")";
  r.note = s.str();
  return r;
}

ThresholdRule threshold_from_crease_angle(double angle_deg, double c0, bool c0_from_config,
                                          bool angle_from_config) {
  if (!(angle_deg > 0 && angle_deg < 180))
    throw std::invalid_argument("the crease angle must lie in (0, 180) degrees");
  ThresholdRule r = absolute_threshold(2.0 * std::sin(angle_deg * std::numbers::pi / 360.0), c0,
                                       c0_from_config);
  r.kind = ThresholdRule::Kind::CreaseAngle;
  r.angle_deg = angle_deg;
  r.angle_from_config = angle_from_config;
  std::ostringstream s;
  s << "crease when |p| > " << r.threshold << " = 2 sin(" << angle_deg
    << " deg / 2), "
    << (angle_from_config ? "output.crease_angle of the run's /config"
                          : "given with --crease-angle")
    << ": a permanent fold of more than "
    << angle_deg << " degrees, the same on every mesh";
  if (c0 > 0) s << " (that is " << r.factor << " c0, " << c0_source(r) << ")";
  r.note = s.str();
  return r;
}

}  // namespace crumple::analysis
