// Assembly of a run (simulation.hpp).
#include "sim/assemble/simulation.hpp"

namespace crumple {

namespace {

/// Self-contact built and added to the model before the integrator sees the model's terms.
std::unique_ptr<SelfContact> make_contact(const Params& p, const Mesh& mesh, SheetModel& model,
                                          const ContactSettings& cs) {
  if (!p.contact.enabled) return nullptr;
  auto contact = std::make_unique<SelfContact>(mesh, cs, p.contact.fold_barrier);
  contact->add_to(model);
  return contact;
}

}  // namespace

Simulation::Simulation(const Params& p, const Mesh& mesh, const StageRegistry& registry,
         ProgressDisplay display, std::function<int()> stop_requested)
    : p_(p),
      material_(resolve_material(p.material, mesh.total_area(), mesh.num_nodes())),
      info_(sheet_info(mesh, material_, p.mesh.size)),
      model_(mesh, material_.model),
      contact_settings_(crumple::contact_settings(p, mesh, material_, &raised_)),
      contact_(make_contact(p, mesh, model_, contact_settings_)),
      contact_on_(contact_ != nullptr),
      integ_(model_, integrator_settings(p, mesh)),
      stepper_(integ_) {
  if (contact_)
    // True when a re-search found a pair in range that the old list lacked: the explicit
    // step's reused last stage (FSAL) was evaluated without it.
    integ_.before_step = [this](const State& st) { return contact_on_ && contact_->update(st.x); };
  RunnerSettings rs = runner_settings(p);
  rs.quiet = display.quiet;
  rs.label = std::move(display.label);
  rs.in_place = display.in_place;
  rs.stop_requested = std::move(stop_requested);
  const YAML::Node& stages = p.protocol.stages;
  runner_ = std::make_unique<ProtocolRunner>(
      model_, stepper_,
      [this, &registry](int k) {
        return registry.make(p_.protocol.stages[k], p_.protocol.stages_source,
                             "protocol.stages[" + std::to_string(k) + "]", &p_.protocol.stage_sets);
      },
      static_cast<int>(stages.size()), info_, rs);
  if (contact_)
    runner_->set_contact_switch(
        [this](bool on) {
          if (on == contact_on_) return;
          if (on)
            contact_->add_to(model_);
          else
            contact_->remove_from(model_);
          contact_on_ = on;
        },
        [this] { return contact_on_; });
}

}  // namespace crumple
