// Mesh quality figures (sim/mesh/quality.hpp) on meshes whose figures are known by hand, and
// the topology checks of build_mesh that generated meshes rely on.
#include "sim/mesh/quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace crumple {
namespace {

Eigen::Matrix3Xd positions(std::initializer_list<Vec3> pts) {
  Eigen::Matrix3Xd ref(3, static_cast<Index>(pts.size()));
  Index i = 0;
  for (const auto& p : pts) ref.col(i++) = p;
  return ref;
}

TEST(MeshQuality, UnitSquareSplitAlongADiagonal) {
  // Nodes 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1); edges 01 12 02 23 03.
  const Mesh m = build_mesh(positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}),
                            {{0, 1, 2}, {0, 2, 3}});
  const MeshQuality q = mesh_quality(m);
  EXPECT_NEAR(q.min_angle_deg, 45.0, 1e-12);
  const double mean = (4.0 + std::sqrt(2.0)) / 5.0;
  const double d1 = 1.0 - mean, d2 = std::sqrt(2.0) - mean;
  const double var = (4.0 * d1 * d1 + d2 * d2) / 5.0;
  EXPECT_NEAR(q.mean_edge, mean, 1e-15);
  EXPECT_NEAR(q.edge_cv, std::sqrt(var) / mean, 1e-15);
  EXPECT_NEAR(q.min_area, 0.5, 1e-15);
  EXPECT_NEAR(q.max_area, 0.5, 1e-15);
  EXPECT_EQ(q.nodes, 4);
  EXPECT_EQ(q.triangles, 2);
  EXPECT_EQ(q.edges, 5);
  EXPECT_EQ(q.hinges, 1);
  EXPECT_EQ(q.boundary_nodes, 4);
  EXPECT_NEAR(mean_index_gap(m), (1 + 1 + 2 + 1 + 3) / 5.0, 1e-15);
}

TEST(MeshQuality, EquilateralTriangleHasNoSpread) {
  const Mesh m = build_mesh(positions({{0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0}}), {{0, 1, 2}});
  const MeshQuality q = mesh_quality(m);
  EXPECT_NEAR(q.min_angle_deg, 60.0, 1e-12);
  EXPECT_NEAR(q.mean_edge, 2.0, 1e-15);
  EXPECT_NEAR(q.edge_cv, 0.0, 1e-15);
  EXPECT_NEAR(q.min_area, std::sqrt(3.0), 1e-15);
  EXPECT_EQ(q.hinges, 0);
}

TEST(MeshQuality, SmallAnglesAreMeasuredAccurately) {
  // A needle of angle 1e-6 rad at node 0, where acos of a dot product would lose digits.
  const double eps = 1e-6;
  const Mesh m = build_mesh(positions({{0, 0, 0}, {1, 0, 0}, {std::cos(eps), std::sin(eps), 0}}),
                            {{0, 1, 2}});
  const double expected = eps * 180.0 / std::numbers::pi;
  EXPECT_NEAR(mesh_quality(m).min_angle_deg, expected, 1e-9 * expected);
}

TEST(BuildMesh, RejectsAnEdgeSharedByThreeTriangles) {
  const auto ref = positions({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0.5, 1}});
  EXPECT_THROW(build_mesh(ref, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), std::invalid_argument);
  EXPECT_NO_THROW(build_mesh(ref, {{0, 1, 2}, {1, 0, 3}}));
}

TEST(BuildMesh, ReorientsClockwiseTriangles) {
  const Mesh m = build_mesh(positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), {{0, 2, 1}});
  const Vec3 a = m.ref.col(m.triangles[0][0]), b = m.ref.col(m.triangles[0][1]),
             c = m.ref.col(m.triangles[0][2]);
  EXPECT_GT((b - a).cross(c - a).z(), 0.0);
}

}  // namespace
}  // namespace crumple
