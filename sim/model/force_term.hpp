// The interface every force term implements: energy, force and Jacobian blocks on the state.
//
// A term is a function of (x, v, p). It returns its energy (zero for dissipative terms), adds
// its force F = -dE/dx (plus any velocity-dependent part) into a 3n vector, and adds its
// Jacobian blocks Hx = -dF/dx and Hv = -dF/dv into matrices on the model's BlockPattern, and
// Hp = -dF/dp into a 3n x n_hinges matrix. Internal terms (springs, bending, damping), contact
// and the external terms of protocol stages (walls, pistons, tethers) all implement it, and one
// finite-difference checker (tests/support/finite_diff.hpp) tests them all.
#pragma once

#include "sim/model/block_pattern.hpp"
#include "sim/model/state.hpp"

#include <string>

namespace crumple {

struct Jacobians {
  SpMat Hx;     ///< -dF/dx, 3n x 3n, on the pattern
  SpMat Hv;     ///< -dF/dv, 3n x 3n, on the pattern
  SpMatCol Hp;  ///< -dF/dp, 3n x n_hinges (left empty when not requested)

  /// Sets Hx and Hv to the zero matrix of the pattern (keeps the structure).
  void reset(const BlockPattern& pattern) {
    Hx = pattern.zero_matrix();
    Hv = pattern.zero_matrix();
  }
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual std::string name() const = 0;
  /// True when the force is minus the gradient of energy() (checked by the FD tests).
  virtual bool conservative() const { return true; }
  virtual double energy(const State& s) const = 0;
  virtual void add_force(const State& s, VecX& f) const = 0;
  /// Adds Hx, Hv into J (on the pattern the term was built with) and, if J.Hp has the right
  /// size, Hp. Terms that need pattern entries report them through coupled_pairs().
  virtual void add_jacobians(const State& s, Jacobians& J) const = 0;
  /// Node pairs this term couples in Hx or Hv, for building the BlockPattern.
  virtual void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const = 0;
  /// Rebuild cached slots after the pattern changed.
  virtual void bind(const BlockPattern& pattern) = 0;
  /// Changes whenever the set returned by coupled_pairs() changes (contact pairs, say); terms
  /// with a fixed stencil keep 0. SheetModel::rebuild_pattern() looks only at this number.
  virtual std::uint64_t pattern_version() const { return 0; }
};

}  // namespace crumple
