// Self-contact as the simulator uses it: the pairwise site repulsion (contact_term.hpp) and the
// fold barrier (fold_barrier.hpp), added to and removed from a model together, with the update
// call the integrator makes before each step.
#pragma once

#include "sim/contact/contact_term.hpp"
#include "sim/contact/fold_barrier.hpp"
#include "sim/model/sheet_model.hpp"

#include <memory>

namespace crumple {

struct SelfContact {
  std::shared_ptr<ContactTerm> pairs;
  std::shared_ptr<FoldBarrierTerm> folds;  ///< null when the barrier is off

  SelfContact(const Mesh& mesh, const ContactSettings& settings, bool fold_barrier = true)
      : pairs(std::make_shared<ContactTerm>(mesh, settings)) {
    if (fold_barrier) folds = std::make_shared<FoldBarrierTerm>(mesh, settings.ks, settings.sigma);
  }
  void add_to(SheetModel& model) const {
    model.add_term(pairs, TermKind::Contact);
    if (folds) model.add_term(folds, TermKind::Contact);
  }
  void remove_from(SheetModel& model) const {
    model.remove_term(pairs.get());
    if (folds) model.remove_term(folds.get());
  }
  /// Refreshes the candidate pairs at x; true if the force at x may have changed (a pair came
  /// into range that the old list lacked), the value Integrator::before_step returns.
  bool update(const VecX& x) const { return pairs->update(x); }
};

}  // namespace crumple
