// The smooth imperfection seeded by compressing stages (protocols/stages/imperfection.hpp):
// requested RMS, smooth on the mesh scale, reproducible from the seed.
#include "protocols/stages/imperfection.hpp"
#include "sim/mesh/generate.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace crumple;
using namespace crumple::stages;

namespace {

Mesh disk(int nodes) { return generate_mesh(MeshSpec{"disk", 0.1, nodes, 3}); }

ImperfectionSpec spec_for(double rms) {
  ImperfectionSpec s;
  s.rms = rms;
  s.shortest = 0.1 / 8;
  s.longest = 0.1 / 2;
  return s;
}

}  // namespace

TEST(Imperfection, HasTheRequestedRmsAndIsReproducible) {
  const Mesh m = disk(1500);
  std::mt19937_64 a(7), b(7), c(8);
  const VecX w1 = smooth_imperfection(m, spec_for(2e-5), a);
  const VecX w2 = smooth_imperfection(m, spec_for(2e-5), b);
  const VecX w3 = smooth_imperfection(m, spec_for(2e-5), c);
  EXPECT_NEAR(std::sqrt(w1.squaredNorm() / w1.size()), 2e-5, 1e-12);
  EXPECT_EQ(w1, w2);
  EXPECT_GT((w1 - w3).norm(), 0.1 * w1.norm());
  EXPECT_EQ(smooth_imperfection(m, spec_for(0.0), a).norm(), 0.0);
}

TEST(Imperfection, IsSmoothOnTheMeshScale) {
  // Across an edge of length l a field with wavelengths >= L/8 changes by about rms q l with
  // q ~ 29/L the RMS wavenumber of the log-uniform band (0.25 rms at 4000 nodes); white noise of
  // the same RMS changes by 2/sqrt(pi) rms = 1.13 rms on average.
  const Mesh m = disk(4000);
  std::mt19937_64 rng(11);
  const double rms = 1e-5;
  const VecX w = smooth_imperfection(m, spec_for(rms), rng);
  std::normal_distribution<double> gauss(0.0, rms);
  VecX noise(w.size());
  for (Index i = 0; i < noise.size(); ++i) noise[i] = gauss(rng);
  auto mean_jump = [&](const VecX& f) {
    double s = 0;
    for (const auto& e : m.edges) s += std::abs(f[e[0]] - f[e[1]]);
    return s / static_cast<double>(m.num_edges());
  };
  EXPECT_GT(mean_jump(w), 0.0);
  EXPECT_LT(mean_jump(w), 0.4 * mean_jump(noise));
}
