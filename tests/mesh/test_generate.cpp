// Generated sheets (sim/mesh/generate.hpp): quality, topology, geometry, determinism and
// Hilbert locality of square and disk meshes at about 1000 and 3000 nodes.
#include "sim/mesh/generate.hpp"
#include "sim/mesh/quality.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <random>

namespace crumple {
namespace {

// Each mesh is generated once and shared by the tests that inspect it.
const Mesh& cached_mesh(const std::string& shape, int nodes) {
  static std::map<std::pair<std::string, int>, Mesh> cache;
  auto it = cache.find({shape, nodes});
  if (it == cache.end()) {
    MeshSpec spec;
    spec.shape = shape;
    spec.nodes = nodes;
    spec.seed = 12345;
    it = cache.emplace(std::make_pair(shape, nodes), generate_mesh(spec)).first;
  }
  return it->second;
}

struct Case {
  std::string shape;
  int nodes;
};

class GeneratedMesh : public ::testing::TestWithParam<Case> {
 protected:
  const Mesh& mesh() const { return cached_mesh(GetParam().shape, GetParam().nodes); }
  double size() const { return MeshSpec{}.size; }
};

TEST_P(GeneratedMesh, QualityMeetsDesignTargets) {
  const MeshQuality q = mesh_quality(mesh());
  EXPECT_GE(q.min_angle_deg, 20.0);
  EXPECT_LE(q.edge_cv, 0.2);
  EXPECT_NEAR(q.nodes, GetParam().nodes, 0.05 * GetParam().nodes);
  RecordProperty("min_angle_deg", std::to_string(q.min_angle_deg));
  RecordProperty("edge_cv", std::to_string(q.edge_cv));
}

TEST_P(GeneratedMesh, TopologyIsADisk) {
  const Mesh& m = mesh();
  // A triangulated topological disk has Euler characteristic 1.
  EXPECT_EQ(m.num_nodes() - m.num_edges() + m.num_triangles(), 1);
  Index interior_edges = 0;
  for (const auto& et : m.edge_triangles) interior_edges += et[1] >= 0;
  EXPECT_EQ(m.num_hinges(), interior_edges);
  EXPECT_EQ(m.shape, GetParam().shape);
}

TEST_P(GeneratedMesh, HingeNormalsPointUpInTheFlatState) {
  const Mesh& m = mesh();
  for (const Hinge& h : m.hinges) {
    const Vec3 x0 = m.ref.col(h.nodes[0]), x1 = m.ref.col(h.nodes[1]);
    const Vec3 x2 = m.ref.col(h.nodes[2]), x3 = m.ref.col(h.nodes[3]);
    const Vec3 e0 = x1 - x0;
    ASSERT_GT(e0.cross(x2 - x0).z(), 0.0);
    ASSERT_GT((x3 - x0).cross(e0).z(), 0.0);
  }
}

TEST_P(GeneratedMesh, SheetIsFlatCentredAndFillsTheOutline) {
  const Mesh& m = mesh();
  EXPECT_EQ(m.ref.row(2).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::Vector2d centroid = m.ref.topRows(2).rowwise().mean();
  EXPECT_LT(centroid.norm(), 0.02 * size());

  const double half = 0.5 * size();
  const Index nb = mesh_quality(m).boundary_nodes;
  double expected = size() * size();
  if (GetParam().shape == "disk")  // the polygon of the boundary nodes
    expected = 0.5 * nb * half * half * std::sin(2.0 * std::numbers::pi / nb);
  EXPECT_NEAR(m.total_area(), expected, 1e-12 * expected);
}

TEST_P(GeneratedMesh, BoundaryNodesLieOnTheBorderAndOnlyThere) {
  const Mesh& m = mesh();
  const double half = 0.5 * size();
  const bool disk = GetParam().shape == "disk";
  const double spacing = m.mean_edge_length();
  Index corners = 0;
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const Eigen::Vector2d p = m.ref.col(i).head<2>();
    const double r = disk ? p.norm() : p.cwiseAbs().maxCoeff();
    if (m.boundary[i]) {
      ASSERT_NEAR(r, half, 1e-14 * half) << "node " << i;
      corners += !disk && std::abs(std::abs(p.x()) - half) < 1e-14 * half &&
                 std::abs(std::abs(p.y()) - half) < 1e-14 * half;
    } else {
      ASSERT_LT(r, half - 0.2 * spacing) << "interior node " << i << " at the border";
    }
  }
  if (!disk) {
    EXPECT_EQ(corners, 4);
  }
}

TEST_P(GeneratedMesh, NoSliverAlongTheBorder) {
  // The hull is the polygon of the boundary nodes. A triangle of three boundary nodes is a
  // sliver on a disk's hull (its corners are nearly collinear); on a square it can only be the
  // right-angled triangle that cuts off a corner.
  const Mesh& m = mesh();
  const double half = 0.5 * size();
  for (const auto& t : m.triangles) {
    if (!(m.boundary[t[0]] && m.boundary[t[1]] && m.boundary[t[2]])) continue;
    ASSERT_EQ(GetParam().shape, "square");
    bool has_corner = false;
    for (Index v : t)
      has_corner = has_corner || (std::abs(m.ref(0, v)) == half && std::abs(m.ref(1, v)) == half);
    ASSERT_TRUE(has_corner);
  }
}

TEST_P(GeneratedMesh, HilbertOrderKeepsNeighboursClose) {
  const Mesh& m = mesh();
  std::vector<Index> perm(m.num_nodes());
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937_64 rng(3);
  std::shuffle(perm.begin(), perm.end(), rng);
  const double hilbert = mean_index_gap(m), scrambled = mean_index_gap(renumber_nodes(m, perm));
  EXPECT_LT(hilbert, 0.1 * scrambled);
  RecordProperty("mean_index_gap", std::to_string(hilbert));
}

INSTANTIATE_TEST_SUITE_P(Sheets, GeneratedMesh,
                         ::testing::Values(Case{"square", 1000}, Case{"disk", 1000},
                                           Case{"square", 3000}, Case{"disk", 3000}),
                         [](const auto& info) {
                           return info.param.shape + std::to_string(info.param.nodes);
                         });

bool identical(const Mesh& a, const Mesh& b) {
  return a.ref.cols() == b.ref.cols() && (a.ref.array() == b.ref.array()).all() &&
         a.triangles == b.triangles;
}

TEST(GenerateMesh, SameSeedGivesTheSameMeshAndAnotherSeedAnother) {
  for (const char* shape : {"square", "disk"}) {
    MeshSpec spec;
    spec.shape = shape;
    spec.nodes = 500;
    spec.seed = 99;
    const Mesh a = generate_mesh(spec), b = generate_mesh(spec);
    EXPECT_TRUE(identical(a, b)) << shape;
    spec.seed = 100;
    const Mesh c = generate_mesh(spec);
    EXPECT_FALSE(identical(a, c)) << shape;
  }
}

TEST(GenerateMesh, SizeScalesTheSheet) {
  MeshSpec spec;
  spec.shape = "disk";
  spec.nodes = 400;
  spec.size = 1.0;
  const Mesh unit = generate_mesh(spec);
  spec.size = 0.1;
  const Mesh small = generate_mesh(spec);
  ASSERT_EQ(unit.num_nodes(), small.num_nodes());
  EXPECT_NEAR(small.ref.topRows(2).colwise().norm().maxCoeff(), 0.05, 1e-15);
  EXPECT_NEAR(small.total_area() / unit.total_area(), 0.01, 1e-12);
  // Lloyd and Delaunay commute with scaling, so the small sheet is the unit one scaled.
  ASSERT_EQ(unit.triangles, small.triangles);
  EXPECT_LT((small.ref - 0.1 * unit.ref).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GenerateMesh, LloydIterationsRegulariseTheRandomStart) {
  MeshSpec spec;
  spec.nodes = 1000;
  spec.lloyd_iterations = 0;
  const MeshQuality raw = mesh_quality(generate_mesh(spec));
  spec.lloyd_iterations = 60;
  const MeshQuality relaxed = mesh_quality(generate_mesh(spec));
  EXPECT_LT(relaxed.edge_cv, 0.5 * raw.edge_cv);
  EXPECT_GT(relaxed.min_angle_deg, raw.min_angle_deg);
}

TEST(GenerateMesh, SmallestMeshIsValid) {
  for (const char* shape : {"square", "disk"}) {
    MeshSpec spec;
    spec.shape = shape;
    spec.nodes = 10;
    const Mesh m = generate_mesh(spec);
    EXPECT_NEAR(m.num_nodes(), 10, 1) << shape;
    EXPECT_EQ(m.num_nodes() - m.num_edges() + m.num_triangles(), 1) << shape;
  }
}

TEST(GenerateMesh, RejectsBadSpecs) {
  auto with = [](auto change) {
    MeshSpec s;
    change(s);
    return s;
  };
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.shape = "circle"; })), std::invalid_argument);
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.nodes = 9; })), std::invalid_argument);
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.size = 0.0; })), std::invalid_argument);
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.size = -1.0; })), std::invalid_argument);
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.size = std::nan(""); })),
               std::invalid_argument);
  EXPECT_THROW(generate_mesh(with([](MeshSpec& s) { s.lloyd_iterations = -1; })),
               std::invalid_argument);
  try {
    generate_mesh(with([](MeshSpec& s) { s.shape = "circle"; }));
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("disk, square"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace crumple

TEST(GenerateMesh, PhysicalSizesWithInexactHalfSides) {
  // Half sides such as 0.05 m are not binary fractions: the border nodes must still be exactly
  // collinear, or the Delaunay hull departs from the border polygon.
  for (const char* shape : {"square", "disk"})
    for (double size : {0.1, 0.37, 0.3}) {
      crumple::MeshSpec spec;
      spec.shape = shape;
      spec.size = size;
      spec.nodes = 400;
      spec.seed = 2;
      EXPECT_NO_THROW(crumple::generate_mesh(spec)) << shape << " of size " << size;
    }
}
