// The physics rules of a run's setup (sim/assemble/sheet_setup.hpp): the contact range is h_eff
// where the mesh resolves it and half an edge where it does not; the config's explicit values
// win; the stages see the resolved material; a yield radius becomes the yield curvature of
// each mesh's hinges.
#include "sim/assemble/sheet_setup.hpp"
#include "sim/contact/contact_sites.hpp"
#include "sim/core/errors.hpp"
#include "sim/mesh/generate.hpp"
#include "sim/mesh/quality.hpp"
#include "sim/model/hinge_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

using namespace crumple;

namespace {
ResolvedMaterial mylar(const Mesh& mesh, double thickness) {
  MaterialParams m;
  m.thickness = thickness;
  return resolve_material(m, mesh.total_area(), mesh.num_nodes());
}
}  // namespace

TEST(ContactSettings, RangeIsHeffUnlessTheMeshIsTooCoarse) {
  const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, 400, 1});
  const double half_edge = 0.5 * mesh.mean_edge_length();
  bool raised = false;
  // 0.25 mm on a 400-node 10 cm sheet (edge about 5 mm): far below half an edge.
  const ResolvedMaterial thin = mylar(mesh, 2.5e-4);
  ContactSettings cs = contact_settings(ContactParams{}, mesh, thin, &raised);
  EXPECT_TRUE(raised);
  EXPECT_DOUBLE_EQ(cs.sigma, half_edge);
  // A sheet thicker than half an edge keeps sigma = h_eff.
  const ResolvedMaterial thick = mylar(mesh, 4 * half_edge);
  cs = contact_settings(ContactParams{}, mesh, thick, &raised);
  EXPECT_FALSE(raised);
  EXPECT_NEAR(cs.sigma, thick.h_eff, 1e-15);
  EXPECT_NEAR(thick.h_eff, 4 * half_edge, 1e-12);  // h_eff = h (paper eq. 5-7)
}

TEST(ContactSettings, ZeroFloorKeepsHeffAndRefinesTheSites) {
  const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, 400, 1});
  const double l = mesh.mean_edge_length();  // about 5 mm
  ContactParams c;
  c.sigma_floor = 0;
  c.max_refinement = kMaxContactRefinement;
  bool raised = true;
  // A 1 mm sheet on this mesh: the range stays h_eff, and auto refines the sites to it.
  const ResolvedMaterial thick = mylar(mesh, 1e-3);
  const ContactSettings cs = contact_settings(c, mesh, thick, &raised);
  EXPECT_FALSE(raised);
  EXPECT_NEAR(cs.sigma, thick.h_eff, 1e-15);
  EXPECT_EQ(cs.max_level, kMaxContactRefinement);
  bool capped = true;
  const int L = auto_refinement(mesh, cs.sigma, &capped, cs.max_level);
  EXPECT_FALSE(capped);
  EXPECT_GT(L, 3);
  EXPECT_LE(l / (L + 1), cs.sigma * (1 + 1e-12));
  // The 0.25 mm sheet: even at level 15 the sites are a sixteenth of an edge, 0.33 mm, apart,
  // more than h; with the floor lowered that is an input error naming the keys, and so is the
  // 1 mm sheet with the default cap.
  const ResolvedMaterial thin = mylar(mesh, 2.5e-4);
  for (const auto& [mat, cap] : {std::pair{thin, kMaxContactRefinement}, std::pair{thick, 3}}) {
    c.max_refinement = cap;
    try {
      contact_settings(c, mesh, mat);
      ADD_FAILURE() << "no error at max_refinement " << cap;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("contact.max_refinement"), std::string::npos) << what;
      EXPECT_NE(what.find("contact.sigma_floor"), std::string::npos) << what;
    }
  }
  // A floor of a quarter edge raises the range to it on this coarse mesh (level 3 resolves it).
  c.sigma_floor = 0.25;
  c.max_refinement = 3;
  EXPECT_DOUBLE_EQ(contact_settings(c, mesh, thin, &raised).sigma, 0.25 * l);
  EXPECT_TRUE(raised);
  // The defaults never stop short: half an edge at level 3.
  EXPECT_NO_THROW(contact_settings(ContactParams{}, mesh, thin));
}

TEST(ContactSettings, ExplicitValuesWin) {
  const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, 400, 1});
  const ResolvedMaterial mat = mylar(mesh, 2.5e-4);
  ContactParams c;
  c.sigma = 1e-4;
  c.stiffness = 7;
  c.refinement = "2";
  c.skin = 0.25;
  bool raised = true;
  const ContactSettings cs = contact_settings(c, mesh, mat, &raised);
  EXPECT_FALSE(raised);
  EXPECT_EQ(cs.sigma, 1e-4);
  EXPECT_EQ(cs.ks, 7);
  EXPECT_EQ(cs.level, 2);
  EXPECT_EQ(cs.skin, 0.25);
  const ContactSettings d = contact_settings(ContactParams{}, mesh, mat);
  EXPECT_EQ(d.ks, mat.model.ks);
  EXPECT_EQ(d.level, -1);
  EXPECT_EQ(d.skin, ContactSettings{}.skin);
}

TEST(SheetInfo, CarriesTheResolvedMaterial) {
  const Mesh mesh = generate_mesh(MeshSpec{"disk", 0.1, 300, 2});
  const ResolvedMaterial mat = mylar(mesh, 2.5e-4);
  const SheetInfo info = sheet_info(mesh, mat, 0.1);
  EXPECT_EQ(info.size, 0.1);
  EXPECT_EQ(info.area, mesh.total_area());
  EXPECT_EQ(info.h_eff, mat.h_eff);
  EXPECT_EQ(info.ks, mat.model.ks);
  EXPECT_EQ(info.kb, mat.model.kb);
  EXPECT_EQ(info.mass, mat.model.mass);
  EXPECT_EQ(info.spacing, mesh.mean_edge_length());
}

// ---- the yield radius (docs/MODEL.md §7.5) ---------------------------------------------------

namespace {

/// The flat sheet wrapped onto a cylinder of radius r whose axis runs along y.
VecX wrapped_on_cylinder(const Mesh& mesh, double r) {
  VecX x = mesh.ref_flat();
  for (Index i = 0; i < mesh.num_nodes(); ++i) {
    const double u = mesh.ref(0, i);
    x[3 * i] = r * std::sin(u / r);
    x[3 * i + 2] = r * (1.0 - std::cos(u / r));
  }
  return x;
}

/// Mean |c| over the hinges whose edge lies within 10 degrees of the y axis (the cylinder's).
double mean_aligned_curvature(const Mesh& mesh, const VecX& x) {
  double sum = 0;
  int count = 0;
  const auto at = [&](Index i) { return Vec3(x.segment<3>(3 * i)); };
  for (const Hinge& h : mesh.hinges) {
    const Vec3 e = mesh.ref.col(h.nodes[1]) - mesh.ref.col(h.nodes[0]);
    if (std::abs(e.y()) < std::cos(10.0 * M_PI / 180.0) * e.norm()) continue;
    sum += std::abs(hinge_curvature(at(h.nodes[0]), at(h.nodes[1]), at(h.nodes[2]), at(h.nodes[3])));
    ++count;
  }
  return sum / count;
}

}  // namespace

TEST(YieldRadius, BendingTheSheetToItBringsTheHingesAlongTheBendToC0) {
  // The defining property of the conversion, on two meshes of the same sheet: wrapped on a
  // cylinder of radius R_y, the hinges along the cylinder's axis (bent about their own edge)
  // reach c0 on average, while c0 itself halves when the node spacing halves.
  Params p;
  p.material.yield_radius = 0.005;
  std::vector<double> c0s;
  for (int nodes : {1500, 6000}) {
    const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, nodes, 1});
    const double c0 = plastic_c0(p, mesh);
    const double c = mean_aligned_curvature(mesh, wrapped_on_cylinder(mesh, p.material.yield_radius));
    std::printf("yield radius %.1f mm, %d nodes: c0 %.4f, mean |c| of the hinges along the bend %.4f\n",
                1e3 * p.material.yield_radius, nodes, c0, c);
    EXPECT_NEAR(c / c0, 1.0, 0.05) << nodes << " nodes";
    c0s.push_back(c0);
  }
  EXPECT_NEAR(c0s[0] / c0s[1], 2.0, 0.1);
}

TEST(YieldAngle, GivesTheSameC0OnEveryMeshAndTheFoldAngleThatYields) {
  // A fold of angle theta on one hinge has c = 2 sin(theta / 2) whatever the hinge's width, so a
  // yield angle is one c0 on every mesh, and folding a hinge to that angle reaches c0 exactly.
  Params p;
  p.material.yield_angle = 17.25;
  const double expected = 2 * std::sin(17.25 * M_PI / 360);
  for (int nodes : {400, 1500}) {
    const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, nodes, 2});
    EXPECT_NEAR(plastic_c0(p, mesh), expected, 1e-15) << nodes;
    const Params r = resolved_for_mesh(p, mesh);
    EXPECT_TRUE(r.c0_from_mesh);
    EXPECT_EQ(r.integrator.plastic_c0, plastic_c0(p, mesh));
  }
  // One hinge folded to the yield angle: flat pair turned about the shared edge.
  const double t = 17.25 * M_PI / 180;
  const Vec3 x0(0, 0, 0), x1(1, 0, 0), x2(0.4, 1, 0), x3(0.6, -std::cos(t), std::sin(t));
  EXPECT_NEAR(std::abs(hinge_curvature(x0, x1, x2, x3)), expected, 1e-12);
}

TEST(YieldRadius, UnsetLeavesTheConfiguredC0AndTooSmallIsRefused) {
  const Mesh mesh = generate_mesh(MeshSpec{"square", 0.1, 400, 1});
  Params p;
  p.integrator.plastic_c0 = 0.37;
  EXPECT_EQ(plastic_c0(p, mesh), 0.37);
  EXPECT_EQ(integrator_settings(p, mesh).plastic_c0, 0.37);
  const Params same = resolved_for_mesh(p, mesh);
  EXPECT_EQ(same.integrator.plastic_c0, 0.37);
  EXPECT_FALSE(same.c0_from_mesh);
  // c0 = 2 sin(w / (2 R_y)) with w the mean hinge width.
  p.material.yield_radius = 0.01;
  const double w = mean_hinge_width(mesh);
  EXPECT_NEAR(plastic_c0(p, mesh), 2 * std::sin(w / 0.02), 1e-15);
  const Params resolved = resolved_for_mesh(p, mesh);
  EXPECT_TRUE(resolved.c0_from_mesh);
  EXPECT_EQ(resolved.integrator.plastic_c0, plastic_c0(p, mesh));
  EXPECT_EQ(integrator_settings(p, mesh).plastic_c0, plastic_c0(p, mesh));
  // A radius below w / pi would ask a hinge to fold through itself before it yields.
  p.material.yield_radius = 0.9 * w / M_PI;
  try {
    plastic_c0(p, mesh);
    FAIL() << "a yield radius below w / pi was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material.yield_radius"), std::string::npos) << e.what();
  }
}
