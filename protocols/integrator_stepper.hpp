// The hybrid Integrator (sim/integrate) seen through the runner's Stepper interface, with its
// history flattened to numbers for checkpoints.
#pragma once

#include "protocols/runner.hpp"
#include "sim/integrate/integrator.hpp"

namespace crumple {

class IntegratorStepper : public Stepper {
 public:
  explicit IntegratorStepper(Integrator& integrator) : integ_(integrator) {}
  void advance_to(State& s, double t_end) override { integ_.advance_to(s, t_end); }
  void restart() override;
  std::vector<double> save() const override;
  void restore(const std::vector<double>& data) override;
  std::string status() const override;
  long steps() const override { return integ_.summary().steps(); }

 private:
  Integrator& integ_;
};

/// IntegratorHistory as a flat list of numbers and back (throws InputError if malformed).
std::vector<double> flatten(const IntegratorHistory& h);
IntegratorHistory unflatten_history(const std::vector<double>& data);

}  // namespace crumple
