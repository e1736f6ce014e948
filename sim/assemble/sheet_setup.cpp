// The physics rules of a run's setup (sheet_setup.hpp).
#include "sim/assemble/sheet_setup.hpp"

#include "sim/contact/contact_sites.hpp"
#include "sim/core/errors.hpp"
#include "sim/mesh/quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace crumple {

SheetInfo sheet_info(const Mesh& mesh, const ResolvedMaterial& material, double size) {
  SheetInfo info;
  info.size = size;
  info.area = mesh.total_area();
  info.h_eff = material.h_eff;
  info.ks = material.model.ks, info.kb = material.model.kb, info.mass = material.model.mass;
  info.spacing = mesh.mean_edge_length();
  return info;
}

ContactSettings contact_settings(const ContactParams& c, const Mesh& mesh,
                                 const ResolvedMaterial& material, bool* raised) {
  ContactSettings cs;
  cs.ks = c.stiffness > 0 ? c.stiffness : material.model.ks;
  const double floor = c.sigma_floor * mesh.mean_edge_length();
  cs.sigma = c.sigma > 0 ? c.sigma : std::max(material.h_eff, floor);
  if (raised) *raised = c.sigma <= 0 && floor > material.h_eff;
  cs.level = c.refinement == "auto" ? -1 : std::stoi(c.refinement);
  cs.max_level = c.max_refinement;
  cs.skin = c.skin;
  // A range from the floor rule must be resolved by the sites auto may build; otherwise layers
  // slip between sites (an explicit contact.sigma keeps the warning of auto_refinement).
  if (c.sigma <= 0 && cs.level < 0) {
    bool capped = false;
    const int level = auto_refinement(mesh, cs.sigma, &capped, cs.max_level);
    if (capped) {
      std::ostringstream os;
      os << "contact.sigma_floor = " << c.sigma_floor << " keeps the contact range at "
         << cs.sigma << " m, but contact.max_refinement = " << c.max_refinement
         << " stops the sites at level " << level << ", " << mesh.mean_edge_length() / (level + 1)
         << " m apart on this mesh: layers would slip between them. Raise "
            "contact.max_refinement (at most "
         << kMaxContactRefinement << ") or contact.sigma_floor, or refine the mesh";
      throw InputError(os.str());
    }
  }
  return cs;
}

ContactSettings contact_settings(const Params& p, const Mesh& mesh,
                                 const ResolvedMaterial& material, bool* raised) {
  try {
    return contact_settings(p.contact, mesh, material, raised);
  } catch (const InputError& e) {
    throw InputError(p.where("contact.sigma_floor") + ": " + e.what());
  }
}

double plastic_c0(const Params& p, const Mesh& mesh) {
  if (p.material.yield_angle > 0)
    return 2.0 * std::sin(p.material.yield_angle * std::numbers::pi / 360.0);
  const double r_y = p.material.yield_radius;
  if (r_y <= 0) return p.integrator.plastic_c0;
  const double w = mean_hinge_width(mesh);
  const double theta = w / r_y;
  if (!(theta < std::numbers::pi)) {
    std::ostringstream os;
    os << p.where("material.yield_radius") << ": " << r_y
       << " m is smaller than this mesh's mean hinge width over pi (" << w / std::numbers::pi
       << " m): a hinge would have to fold through itself to yield";
    throw InputError(os.str());
  }
  return 2.0 * std::sin(theta / 2.0);
}

IntegratorSettings integrator_settings(const Params& p, const Mesh& mesh) {
  IntegratorSettings s = p.integrator;
  s.plastic_c0 = plastic_c0(p, mesh);
  return s;
}

Params resolved_for_mesh(Params p, const Mesh& mesh) {
  if (!p.material.states_yield()) return p;
  p.integrator.plastic_c0 = plastic_c0(p, mesh);
  p.c0_from_mesh = true;
  return p;
}

RunnerSettings runner_settings(const Params& p) {
  RunnerSettings rs;
  rs.cycles = p.protocol.cycles;
  rs.t_max = p.protocol.t_max;
  rs.frame_dt = p.output.dt;
  rs.checkpoint_wall_s = p.output.checkpoint_wall_s;
  rs.seed = p.mesh.seed;
  return rs;
}

}  // namespace crumple
