// One place that assembles a run: from resolved parameters and a mesh to the sheet model, its
// self-contact, the hybrid integrator and the protocol runner, wired together (contact refreshed
// before every step and switched by the stages). crumple-sim builds its run here; so can a
// benchmark or a test that wants the simulator's setup without its files.
#pragma once

#include "protocols/integrator_stepper.hpp"
#include "protocols/registry.hpp"
#include "protocols/runner.hpp"
#include "sim/assemble/sheet_setup.hpp"
#include "sim/contact/self_contact.hpp"
#include "sim/integrate/integrator.hpp"
#include "sim/model/sheet_model.hpp"

#include <memory>

namespace crumple {

/// How a run shows its progress (RunnerSettings): silent, or lines named `label`, overwritten in
/// place on a terminal.
struct ProgressDisplay {
  bool quiet = true;
  std::string label;
  bool in_place = false;
};

class Simulation {
 public:
  /// `p` and `mesh` must outlive the run (the stages read p's stage list, the terms the mesh).
  /// `stop_requested` is polled after every chunk of steps (RunnerSettings).
  Simulation(const Params& p, const Mesh& mesh, const StageRegistry& registry,
      ProgressDisplay display = {}, std::function<int()> stop_requested = [] { return 0; });
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Runs the protocol from `s` (the rest state, or the checkpoint's when resuming).
  bool run(State& s, RunSink& sink, const Checkpoint* resume = nullptr) {
    return runner_->run(s, sink, resume);
  }

  const ResolvedMaterial& material() const { return material_; }
  const SheetInfo& sheet() const { return info_; }
  SheetModel& model() { return model_; }
  Integrator& integrator() { return integ_; }
  ProtocolRunner& runner() { return *runner_; }
  /// Null when contact is off in the config.
  const SelfContact* contact() const { return contact_.get(); }
  const ContactSettings& contact_settings() const { return contact_settings_; }
  /// True when the contact range was raised to half an edge (mesh too coarse for h_eff).
  bool contact_range_raised() const { return raised_; }

 private:
  const Params& p_;
  ResolvedMaterial material_;
  SheetInfo info_;
  SheetModel model_;
  ContactSettings contact_settings_;
  bool raised_ = false;
  std::unique_ptr<SelfContact> contact_;
  bool contact_on_ = false;
  Integrator integ_;
  IntegratorStepper stepper_;
  std::unique_ptr<ProtocolRunner> runner_;
};

}  // namespace crumple
