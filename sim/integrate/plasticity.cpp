// The plastic flow law (plasticity.hpp; paper eq. 17-20).
#include "sim/integrate/plasticity.hpp"

#include <cmath>

namespace crumple {

double PlasticLaw::smoothstep(double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}

double PlasticLaw::smoothstep_derivative(double x) {
  if (x <= 0.0 || x >= 1.0) return 0.0;
  const double y = x * (1.0 - x);
  return 30.0 * y * y;
}

double PlasticLaw::f(double lambda) const {
  if (!enabled) return 0.0;
  return rate * smoothstep((lambda - c0) / (2.0 - c0)) / (1.0 + gamma);
}

double PlasticLaw::df(double lambda) const {
  if (!enabled) return 0.0;
  const double w = 1.0 / (2.0 - c0);
  return rate * w * smoothstep_derivative((lambda - c0) * w) / (1.0 + gamma);
}

double PlasticLaw::g(double c, double p) const {
  const double u = c - p;
  // sgn(u) f(|u|): continuous through u = 0 because f vanishes on the dead band.
  return u > 0.0 ? f(u) : -f(-u);
}

double PlasticLaw::dg_dc(double c, double p) const { return df(std::abs(c - p)); }

}  // namespace crumple
