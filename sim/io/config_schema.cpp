// The sections of the configuration other than the integrator's (config_schema.hpp). Upper
// bounds keep a typo from a run of days or an allocation that fails: 1e6 nodes is 20x the largest
// sheet studied, Lloyd converges in tens of iterations, a frame every microsecond of simulated
// time is already a million frames per second.
#include "sim/io/config_schema.hpp"

#include "sim/contact/contact_sites.hpp"
#include "sim/integrate/settings_schema.hpp"

namespace crumple {

namespace {

using namespace schema;

Section mesh_section() {
  using S = MeshSpec;
  Section s;
  s.name = "mesh";
  s.meaning = "the flat sheet: outline, size and resolution (sim/mesh/generate.hpp)";
  s.keys = {
      word("shape", &S::shape, {"square", "disk"}).means("sheet outline, centred at the origin in z = 0"),
      integer("nodes", &S::nodes).in(10, 1e6).means("approximate node count: the resolution knob"),
      real("size", &S::size).above(0).units("m").means("side length (square) or diameter (disk)"),
      // 2^53: seeds are stored as YAML numbers, exact up to there.
      integer("seed", &S::seed).in(0, 9007199254740992.0)
          .means("seed of the mesh and of the protocol's random choices; --seed sets it"),
      integer("lloyd_iterations", &S::lloyd_iterations).in(0, 1000)
          .means("Lloyd (centroidal Voronoi) regularisation steps"),
  };
  return s;
}

Section material_section() {
  using S = MaterialParams;
  Section s;
  s.name = "material";
  s.meaning = "the sheet's material (paper eq. 5-7), or the model constants directly";
  s.keys = {
      real("thickness", &S::thickness).above(0).units("m").means("sheet thickness h (becomes h_eff)"),
      real("young_modulus", &S::young_modulus).above(0).units("Pa").means("Young's modulus Y"),
      real("density", &S::density).above(0).units("kg/m^3")
          .means("node mass m = mass_scale density h A / n"),
      real("poisson", &S::poisson).in(1.0 / 3.0 - 1e-12, 1.0 / 3.0 + 1e-12).shown_range("= 1/3").shown_default("1/3")
          .means("Poisson ratio, fixed by the triangular spring network (Appendix A)"),
      real("ks", &S::ks).above(0).units("N/m").unset_when_zero().shown_default("unset")
          .means("spring constant given directly (with kb and mass)"),
      real("kb", &S::kb).above(0).units("J").unset_when_zero().shown_default("unset")
          .means("bending constant given directly (with ks and mass)"),
      real("mass", &S::mass).above(0).units("kg").unset_when_zero().shown_default("unset")
          .means("node mass given directly (with ks and kb)"),
      real("mass_scale", &S::mass_scale).above(0)
          .means("multiplies the node mass (mass scaling for quasistatic loading)"),
      real("drag_ratio", &S::drag_ratio).at_least(0)
          .means("isotropic drag b_iso = ratio sqrt(ks m) (eq. 8)"),
      real("internal_damping_ratio", &S::internal_damping_ratio).at_least(0)
          .means("dashpots b_int = ratio sqrt(ks m) (eq. 9)"),
      real("yield_radius", &S::yield_radius).at_least(0).units("m")
          .unset_when_zero().shown_default("0: unset")
          .means("yield radius of curvature: sets integrator.plastic_c0 on each mesh to "
                 "2 sin(w / (2 R_y)), w the mean hinge width (docs/MODEL.md §7.5); 0 unsets a "
                 "protocol's radius, so that a yield angle or c0 can be given instead"),
      real("yield_angle", &S::yield_angle).at_least(0).below(180).units("deg")
          .unset_when_zero().shown_default("0: unset")
          .means("yield fold angle: a fold sharper than it yields; sets integrator.plastic_c0 "
                 "to 2 sin(angle / 2) on every mesh (docs/MODEL.md §7.6); 0 unsets a protocol's "
                 "angle, so that a yield radius or c0 can be given instead"),
      flag("area_barrier", &S::area_barrier)
          .means("keep every triangle from being pressed flat: a barrier below half its rest "
                 "area (sim/model/area_barrier.hpp)"),
  };
  s.all_or_none = {"ks", "kb", "mass"};
  return s;
}

// "auto" and every level build_contact_sites makes.
std::vector<std::string> refinement_choices() {
  std::vector<std::string> c{"auto"};
  for (int L = 0; L <= kMaxContactRefinement; ++L) c.push_back(std::to_string(L));
  return c;
}

Section contact_section() {
  using S = ContactParams;
  Section s;
  s.name = "contact";
  s.meaning = "self-contact of the sheet (paper §2.4, eq. 10-12)";
  s.keys = {
      flag("enabled", &S::enabled).means("self-contact on or off"),
      real("sigma", &S::sigma).at_least(0).units("m").shown_default("0: h_eff")
          .means("interaction range; 0: h_eff, raised to sigma_floor edges on coarse meshes"),
      real("sigma_floor", &S::sigma_floor).at_least(0).units("edges")
          .means("with sigma = 0, the least range in mean edge lengths; 0: h_eff on every mesh, "
                 "with the sites refined to it (max_refinement; docs/MODEL.md §6.6)"),
      word("refinement", &S::refinement, refinement_choices())
          .means("contact-site refinement level (Fig. 2); auto: sites at most sigma apart"),
      integer("max_refinement", &S::max_refinement).in(0, kMaxContactRefinement)
          .means("the finest level auto may pick; a range from sigma_floor it cannot resolve "
                 "is an input error, an explicit sigma a warning"),
      real("stiffness", &S::stiffness).at_least(0).units("N/m").shown_default("0: ks")
          .means("contact stiffness; 0: the spring constant ks"),
      real("skin", &S::skin).in(0, 10).means("candidate-list skin, as a fraction of sigma"),
      flag("fold_barrier", &S::fold_barrier)
          .means("keep every hinge from folding through itself (sim/contact/fold_barrier.hpp)"),
  };
  return s;
}

Section protocol_section() {
  using S = ProtocolParams;
  Section s;
  s.name = "protocol";
  s.meaning = "the stages a cycle runs, and how often";
  s.keys = {
      integer("cycles", &S::cycles).in(1, 1e6).means("repetitions of the stage list"),
      real("t_max", &S::t_max).above(0).units("s")
          .means("cap on the simulated time of the run (smoke tests)"),
      list("stages").shown_default("[]")
          .means("the stages, each {type: NAME, param: value, ...}; see the stage types below"),
  };
  return s;
}

Section output_section() {
  using S = OutputParams;
  Section s;
  s.name = "output";
  s.meaning = "what the run file stores, and how often";
  s.keys = {
      real("dt", &S::dt).at_least(1e-6).units("s").may_change_on_resume()
          .means("simulated time between stored frames"),
      real("checkpoint_wall_s", &S::checkpoint_wall_s).at_least(0).units("s").may_change_on_resume()
          .means("wall time between checkpoints inside a stage (also at every stage end)"),
      flag("xdmf", &S::xdmf).means("write the ParaView sidecar RUN.xdmf"),
      real("crease_angle", &S::crease_angle).at_least(0).below(180).units("deg")
          .unset_when_zero().shown_default("0: 0.5 c0")
          .means("permanent fold angle above which a hinge counts as a crease (its plastic "
                 "rest curvature above 2 sin(angle / 2)), the same on every mesh: the run file's "
                 "crease masks and crumple-analyze's default threshold; 0: half the yield "
                 "curvature c0, which moves with the mesh under a yield radius "
                 "(docs/STATISTICS.md §5)"),
  };
  return s;
}

/// A section bound to its member of Params.
template <auto Member>
ConfigSection bind(const Section& s) {
  return {&s, [](Params& p) -> void* { return &(p.*Member); },
          [](const Params& p) -> const void* { return &(p.*Member); }};
}

}  // namespace

const std::vector<ConfigSection>& config_schema() {
  static const Section mesh = mesh_section(), material = material_section(),
                       contact = contact_section(), protocol = protocol_section(),
                       output = output_section();
  static const std::vector<ConfigSection> all = {
      bind<&Params::mesh>(mesh),         bind<&Params::material>(material),
      bind<&Params::integrator>(integrator_schema()), bind<&Params::contact>(contact),
      bind<&Params::protocol>(protocol), bind<&Params::output>(output),
  };
  return all;
}

const Key* find_key(const std::string& dotted) {
  const auto dot = dotted.find('.');
  if (dot == std::string::npos) return nullptr;
  for (const auto& cs : config_schema())
    if (cs.section->name == dotted.substr(0, dot)) return cs.section->find(dotted.substr(dot + 1));
  return nullptr;
}

const std::vector<std::pair<std::string, std::string>>& retired_keys() {
  static const std::vector<std::pair<std::string, std::string>> keys = {
      {"output.crease_threshold",
       "retired: the run file stores the plastic field p and crumple-analyze applies the crease "
       "threshold; a protocol states it as output.crease_angle (degrees), else 0.5 c0"},
  };
  return keys;
}

std::vector<std::string> resumable_keys() {
  std::vector<std::string> v;
  for (const auto& cs : config_schema())
    for (const auto& k : cs.section->keys)
      if (k.resumable) v.push_back(cs.section->name + "." + k.name);
  return v;
}

std::string value_text(const Key& key, const void* values) {
  switch (key.kind) {
    case Kind::Word: return key.get_word(values);
    case Kind::Flag: return key.get_number(values) != 0 ? "true" : "false";
    case Kind::List: return "";
    default: return format_number(key.get_number(values));
  }
}

}  // namespace crumple
