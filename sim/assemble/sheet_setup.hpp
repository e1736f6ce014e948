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
/// the config sets them, and on a mesh too coarse to resolve h_eff the range raised to half an
/// edge (with site refinement capped at level 3 the sites are a quarter edge apart, and layers
/// slip between sites unless the range covers them; measured: a flat sheet stays force-free up
/// to 0.79 edge at level 3). `raised` (optional) tells whether that floor applied.
ContactSettings contact_settings(const ContactParams& c, const Mesh& mesh,
                                 const ResolvedMaterial& material, bool* raised = nullptr);

/// The runner's settings from the protocol and output sections and the mesh seed.
RunnerSettings runner_settings(const Params& p);

}  // namespace crumple
