// The physics rules of a run's setup (sheet_setup.hpp).
#include "sim/assemble/sheet_setup.hpp"

#include <algorithm>
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
  const double floor = 0.5 * mesh.mean_edge_length();
  cs.sigma = c.sigma > 0 ? c.sigma : std::max(material.h_eff, floor);
  if (raised) *raised = c.sigma <= 0 && floor > material.h_eff;
  cs.level = c.refinement == "auto" ? -1 : std::stoi(c.refinement);
  cs.skin = c.skin;
  return cs;
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
