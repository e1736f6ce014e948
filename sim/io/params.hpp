// Every parameter of a run, in one typed tree with its defaults (the member initialisers here
// and in the structs it reuses: MeshSpec, IntegratorSettings). Filled from YAML by load_config
// (config.hpp), printed back whole by resolved_yaml and stored in every output file. Keys are
// the member names; their ranges, units and meanings are declared once in config_schema.cpp.
#pragma once

#include "sim/contact/contact_term.hpp"
#include "sim/integrate/settings.hpp"
#include "sim/mesh/generate.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <string>

namespace crumple {

struct MaterialParams {
  // Physical description (paper eq. 5-7), used unless ks, kb and mass are all given.
  double thickness = 2.5e-4;     ///< m (becomes h_eff)
  double young_modulus = 1e9;    ///< Pa
  double density = 1400;         ///< kg/m^3 (Mylar)
  double poisson = 1.0 / 3.0;    ///< fixed by the triangular spring network
  // Direct model constants (all three or none).
  double ks = 0, kb = 0, mass = 0;
  double mass_scale = 1e4;       ///< multiplies the node mass (quasistatic mass scaling)
  double drag_ratio = 0.01;      ///< b_iso = drag_ratio sqrt(ks m)
  double internal_damping_ratio = 0.1;  ///< b_int = ratio sqrt(ks m)
  /// Yield radius of curvature R_y (m): the sheet yields where it is bent tighter than R_y. Set,
  /// it fixes integrator.plastic_c0 on each mesh (sim/assemble/sheet_setup.hpp); 0: unset, the
  /// yield is integrator.plastic_c0 as given.
  double yield_radius = 0;
  /// Yield fold angle theta_y (degrees): a fold sharper than theta_y yields, wherever the mesh
  /// puts it. Set, it fixes integrator.plastic_c0 = 2 sin(theta_y / 2) on every mesh; 0: unset.
  double yield_angle = 0;
  /// Keep every triangle above half its rest area (sim/model/area_barrier.hpp).
  bool area_barrier = true;
  /// True when the material states the yield (yield_radius or yield_angle) and so sets
  /// integrator.plastic_c0.
  bool states_yield() const { return yield_radius > 0 || yield_angle > 0; }
};

struct ContactParams {
  bool enabled = true;
  double sigma = 0;              ///< interaction range (m); 0: h_eff
  double sigma_floor = 0.5;      ///< with sigma = 0, the least range, in mean edge lengths
  std::string refinement = "auto";  ///< auto | 0 .. kMaxContactRefinement
  int max_refinement = 3;        ///< the finest level auto may pick
  double stiffness = 0;          ///< contact stiffness; 0: ks
  double skin = ContactSettings{}.skin;  ///< candidate-list skin, fraction of sigma
  bool fold_barrier = true;      ///< keep hinges from folding through themselves
};

struct ProtocolParams {
  int cycles = 1;
  double t_max = 1e30;           ///< cap on the simulated time of the run (s)
  YAML::Node stages{YAML::NodeType::Sequence};  ///< the stage list, validated by the stage registry
  std::string stages_source;     ///< where the list came from: the file, or "--set protocol.stages=..."
  /// Stage parameters given by `--set protocol.stages.TYPE.KEY=V`: "protocol.stages[k].KEY" ->
  /// "--set ..." as given, so the stage registry names the argument in its messages.
  std::map<std::string, std::string> stage_sets;
};

struct OutputParams {
  double dt = 0.01;              ///< simulated time between frames (s)
  double checkpoint_wall_s = 300;
  bool xdmf = true;
  /// Permanent fold angle (degrees) above which a hinge counts as a crease; 0: half the yield
  /// curvature c0 (sim/model/crease_rule.hpp).
  double crease_angle = 0;
};

struct Params {
  MeshSpec mesh;                 ///< the sheet (sim/mesh/generate.hpp); size in m
  MaterialParams material;
  IntegratorSettings integrator;
  ContactParams contact;
  ProtocolParams protocol;
  OutputParams output;
  std::string file;              ///< the config's path (for messages)
  /// True once integrator.plastic_c0 holds the value material.yield_radius or yield_angle gives
  /// on the run's mesh (sim/assemble/sheet_setup.hpp, resolved_for_mesh); resolved_yaml then
  /// writes it.
  bool c0_from_mesh = false;
  /// Where each key the input gave was set: dotted key -> "FILE:LINE:COL" or "--set key=value"
  /// (for messages about relations checked after loading). Keys left at their default are absent.
  std::map<std::string, std::string> origins;
  /// Where a key was set, or "FILE: key (default)" when it was not.
  std::string where(const std::string& dotted) const {
    auto it = origins.find(dotted);
    return it != origins.end() ? it->second + ": " + dotted : file + ": " + dotted + " (default)";
  }
};

}  // namespace crumple
