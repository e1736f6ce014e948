// The radial-confinement sheet of the benchmarks (paper Fig. 5a): a 10 cm disk, h_eff
// 0.125 mm by default (SheetChoice; the paper's Fig. 5 sheet is 0.25 mm thick, its Fig. 7 one
// 0.125 mm; the issue allows either), Y = 1 GPa, density 1400 kg/m^3 with a mass scale, drag 0.01 and internal
// damping 0.1 of sqrt(ks m) as the protocol files' defaults.
#pragma once

#include "protocols/registry.hpp"
#include "sim/assemble/sheet_setup.hpp"
#include "sim/contact/self_contact.hpp"
#include "sim/io/params.hpp"
#include "sim/mesh/generate.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace crumple {

/// Which radial sheet: its thickness and its mesh. The defaults are
/// protocols/radial_confinement.yaml's sheet; the paper's Fig. 5 sheet is 0.25 mm thick, and
/// another mesh seed is another sample of the same sheet (the events of a run, and with them the
/// hybrid's explicit stretches, differ).
struct SheetChoice {
  double thickness_mm = 0.125;  ///< h_eff
  std::uint64_t mesh_seed = 1;  ///< seed of the mesh's interior points
};

/// --thickness and --mesh-seed, for every program that builds or reloads a radial sheet.
inline void add_sheet_options(CLI::App& app, SheetChoice& c) {
  app.add_option("--thickness", c.thickness_mm, "sheet thickness h_eff in mm (the paper's Fig. 5 "
                 "sheet: 0.25)")
      ->check(CLI::Range(0.01, 10.0));
  app.add_option("--mesh-seed", c.mesh_seed, "seed of the mesh's interior points (another seed: "
                 "another sample of the same sheet)");
}

struct RadialSheet {
  Mesh mesh;
  ResolvedMaterial material;
  ModelParams params;
  SheetInfo info;
  SheetChoice choice;
  double mass_scale = 1.0;
};

inline RadialSheet make_radial_sheet(int nodes, double mass_scale, const SheetChoice& c = {}) {
  RadialSheet s;
  s.choice = c;
  s.mass_scale = mass_scale;
  s.mesh = generate_mesh(MeshSpec{"disk", 0.1, nodes, c.mesh_seed});
  // The config's material (Mylar-like defaults: Y, density, drag, damping) at this thickness,
  // through the simulator's own conversion (sim/io/units.hpp).
  MaterialParams m;
  m.thickness = 1e-3 * c.thickness_mm;
  m.mass_scale = mass_scale;
  s.material = resolve_material(m, s.mesh.total_area(), s.mesh.num_nodes());
  s.params = s.material.model;
  s.info = sheet_info(s.mesh, s.material, 0.1);
  return s;
}

/// What a warm state of `su` was integrated with (bench_radial's warm-up: hybrid, block Jacobi
/// 18); a state is reused only for the same setup. The thickness and the mesh seed are named
/// only when they are not the defaults, so that states saved before they could be chosen keep
/// their description.
inline std::string warm_description(const RadialSheet& su, double force, bool contact) {
  std::string d = "bench_radial warm-up, hybrid block Jacobi 18, force " + std::to_string(force) +
                  (contact ? ", contact" : ", phantom sheet") + ", mass scale " +
                  std::to_string(su.mass_scale);
  if (su.choice.thickness_mm != SheetChoice{}.thickness_mm)
    d += ", thickness " + std::to_string(su.choice.thickness_mm) + " mm";
  if (su.choice.mesh_seed != SheetChoice{}.mesh_seed)
    d += ", mesh seed " + std::to_string(su.choice.mesh_seed);
  return d;
}

/// The radial confinement stage as the protocols write it: cutoff shrinking at 1 cm/s for 5 s,
/// `force` per node beyond it in units of ks h_eff (<= 0: the stage's default).
inline YAML::Node radial_stage_node(double force) {
  YAML::Node n = YAML::Load("{type: radial_confine, speed: 0.01, duration: 5}");
  if (force > 0) n["force"] = force;
  return n;
}

/// Begins the radial confinement stage (begun at t = 0, `force` as radial_stage_node) on
/// `model`, whose terms it extends. The stage gives the sheet its imperfection when it begins:
/// at s.t = 0 that is the state to integrate; a restart from a warm state begins the stage (its
/// wall, its force) on a scratch copy, so the warm state is not displaced a second time.
inline std::unique_ptr<Stage> begin_radial_stage(const RadialSheet& su, SheetModel& model,
                                                 State& s, double force) {
  StageContext ctx;
  ctx.model = &model;
  State scratch = s;
  ctx.state = s.t == 0.0 ? &s : &scratch;
  ctx.sheet = su.info;
  ctx.t_begin = 0.0;
  auto stage = StageRegistry::builtin().make(radial_stage_node(force), "bench", "stage");
  stage->begin(ctx);
  return stage;
}

/// Self-contact as crumple-sim sets it up by default (the config's contact section through the
/// run assembly's rule, sim/assemble/sheet_setup.hpp), added to `model`.
inline std::unique_ptr<SelfContact> add_contact(const RadialSheet& su, SheetModel& model) {
  const ContactSettings cs = contact_settings(ContactParams{}, su.mesh, su.material);
  auto contact = std::make_unique<SelfContact>(su.mesh, cs, ContactParams{}.fold_barrier);
  contact->add_to(model);
  return contact;
}

}  // namespace crumple
