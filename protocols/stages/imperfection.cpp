// Smooth random out-of-plane imperfection (imperfection.hpp).
#include "protocols/stages/imperfection.hpp"

#include <cmath>
#include <stdexcept>

namespace crumple::stages {

VecX smooth_imperfection(const Mesh& mesh, const ImperfectionSpec& spec, std::mt19937_64& rng) {
  const Index n = mesh.num_nodes();
  VecX w = VecX::Zero(n);
  if (spec.rms == 0.0) return w;
  if (!(spec.shortest > 0 && spec.longest >= spec.shortest && spec.modes > 0))
    throw std::invalid_argument("smooth_imperfection: need 0 < shortest <= longest and modes > 0");
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int k = 0; k < spec.modes; ++k) {
    // Wavelength log-uniform in [shortest, longest], direction and phase uniform, amplitude
    // Gaussian; the overall scale is fixed below.
    const double lambda = spec.shortest * std::pow(spec.longest / spec.shortest, uni(rng));
    const double dir = 2.0 * M_PI * uni(rng), phase = 2.0 * M_PI * uni(rng);
    const double amp = gauss(rng);
    const double qx = 2.0 * M_PI / lambda * std::cos(dir), qy = 2.0 * M_PI / lambda * std::sin(dir);
    for (Index i = 0; i < n; ++i) {
      w[i] += amp * std::cos(qx * mesh.ref(0, i) + qy * mesh.ref(1, i) + phase);
    }
  }
  const double rms = std::sqrt(w.squaredNorm() / static_cast<double>(n));
  if (rms > 0) w *= spec.rms / rms;
  return w;
}

}  // namespace crumple::stages
