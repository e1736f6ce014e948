// Bending energy of a flat sheet wrapped onto a cylinder: the discrete energy must approach the
// continuum kappa A / (2 R^2), kappa = sqrt(3) kb / 2 (paper eq. A.10-A.12), independent of the
// roll direction and of the resolution (docs/MODEL.md §4.6: 1.00-1.04 measured on these meshes).
#include "sim/mesh/generate.hpp"
#include "sim/model/bending.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace crumple;

namespace {
double wrapped_energy_ratio(const Mesh& m, double R, double angle) {
  const Vec3 a(std::cos(angle), std::sin(angle), 0), b(-std::sin(angle), std::cos(angle), 0);
  State s;
  s.x.resize(3 * m.num_nodes());
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const Vec3 r = m.ref.col(i);
    const double u = r.dot(b), w = r.dot(a);
    s.x.segment<3>(3 * i) = w * a + R * std::sin(u / R) * b + R * (1 - std::cos(u / R)) * Vec3::UnitZ();
  }
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(m.num_hinges());
  const double kb = 1.0;
  BendingTerm bend(m, kb);
  const double kappa = std::sqrt(3.0) * kb / 2.0;
  return bend.energy(s) / (kappa * m.total_area() / (2 * R * R));
}
}  // namespace

TEST(Cylinder, BendingEnergyMatchesTheContinuum) {
  for (int nodes : {1000, 3000}) {
    MeshSpec spec;
    spec.shape = "square";
    spec.size = 1.0;
    spec.nodes = nodes;
    spec.seed = 5;
    const Mesh m = generate_mesh(spec);
    double lo = 1e9, hi = 0;
    for (double deg : {0.0, 30.0, 70.0}) {
      const double ratio = wrapped_energy_ratio(m, 0.3, deg * M_PI / 180.0);
      SCOPED_TRACE(std::to_string(nodes) + " nodes, axis at " + std::to_string(deg) + " deg");
      EXPECT_GE(ratio, 0.9);
      EXPECT_LE(ratio, 1.25);
      lo = std::min(lo, ratio), hi = std::max(hi, ratio);
      std::printf("cylinder: %d nodes, axis %4.0f deg: E / (kappa A / 2R^2) = %.4f\n", nodes, deg,
                  ratio);
    }
    EXPECT_LE(hi / lo - 1.0, 0.05) << "energy depends on the roll direction";
  }
}
