// From resolved parameters to the pieces of a run, each physics rule written once: the sheet
// the stages see (SheetInfo), the self-contact settings (the contact range rule), and the
// protocol runner's settings. crumple-sim, the benchmarks and the tests all call these
// (simulation.hpp assembles them into a whole run).
#pragma once

#include "protocols/runner.hpp"
#include "sim/contact/contact_term.hpp"
#include "sim/io/params.hpp"
#include "sim/io/units.hpp"
#include "sim/mesh/mesh.hpp"

namespace crumple {

/// What the stages know of the sheet: size (m), area, h_eff, model constants, mean edge.
SheetInfo sheet_info(const Mesh& mesh, const ResolvedMaterial& material, double size);

/// The self-contact settings of a run (paper §2.4): stiffness ks and range sigma = h_eff unless
/// the config sets them, and on a mesh too coarse to resolve h_eff the range raised to
/// contact.sigma_floor edges, half an edge by default (with the default cap on site refinement,
/// level 3, the sites are a quarter edge apart, and layers slip between sites unless the range
/// covers them; measured: a flat sheet stays force-free up to 0.79 edge at level 3). With
/// sigma_floor = 0 the range stays h_eff and the sites are refined to it instead, up to
/// contact.max_refinement (docs/MODEL.md §6.6). `raised` (optional) tells whether the floor
/// applied.
ContactSettings contact_settings(const ContactParams& c, const Mesh& mesh,
                                 const ResolvedMaterial& material, bool* raised = nullptr);

/// The same for a run's parameters: an input error names where in the input the contact keys
/// were set (file, line and key, or the --set that gave them).
ContactSettings contact_settings(const Params& p, const Mesh& mesh,
                                 const ResolvedMaterial& material, bool* raised = nullptr);

/// The hinge yield curvature c0 (paper eq. 19, in units of 2 sin(theta/2)) of a run on `mesh`:
/// integrator.plastic_c0, or, when material.yield_radius R_y is set, the curvature of a hinge of
/// the mesh's mean width w (mean_hinge_width) bent about its edge to the radius R_y,
/// c0 = 2 sin(w / (2 R_y)). A yield radius is a property of the sheet; c0 is per hinge and so
/// per mesh: R_y = 8.1 mm is c0 = 0.30 on the 10 cm sheet at 1500 nodes and 0.105 at 12000
/// (docs/MODEL.md §7.5). When material.yield_angle theta_y is set instead, c0 = 2 sin(theta_y / 2)
/// on every mesh: the yield of a fold narrower than a hinge, which the mesh puts on one hinge
/// (§7.6, with its measured limits). Throws InputError when R_y is so small that w / R_y >= pi.
double plastic_c0(const Params& p, const Mesh& mesh);

/// The integrator's settings of a run on `mesh` (plastic_c0 as above).
IntegratorSettings integrator_settings(const Params& p, const Mesh& mesh);

/// `p` with integrator.plastic_c0 resolved on `mesh`: the configuration a run stores, so that
/// readers of the run file find the c0 it ran with.
Params resolved_for_mesh(Params p, const Mesh& mesh);

/// The runner's settings from the protocol and output sections and the mesh seed.
RunnerSettings runner_settings(const Params& p);

}  // namespace crumple
