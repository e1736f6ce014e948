// The physics rules of a run's setup (sim/assemble/sheet_setup.hpp): the contact range is h_eff
// where the mesh resolves it and half an edge where it does not; the config's explicit values
// win; the stages see the resolved material.
#include "sim/assemble/sheet_setup.hpp"
#include "sim/mesh/generate.hpp"

#include <gtest/gtest.h>

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
