// The sheet model: all force terms on one mesh, their energies, the total force and the
// assembled Jacobians Hx, Hv, Hp (paper eq. 2, 27, 34).
//
// Internal terms (springs, the area barrier, bending, isotropic drag, internal damping) are created from the mesh
// and ModelParams. Further terms (self-contact, the external terms of protocol stages) are added
// with add_term and removed with remove_term; after the set of terms, or the node pairs a term
// couples, has changed, call rebuild_pattern() (cheap when nothing changed).
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/bending.hpp"
#include "sim/model/force_term.hpp"
#include "sim/model/params.hpp"

#include <memory>

namespace crumple {

/// Energy by kind, as stored in the step log.
struct Energies {
  double stretch = 0, bend = 0, contact = 0, external = 0, kinetic = 0;
  double potential() const { return stretch + bend + contact + external; }
  double total() const { return potential() + kinetic; }
};

enum class TermKind { Stretch, Bend, Dissipative, Contact, External };

class SheetModel {
 public:
  SheetModel(const Mesh& mesh, const ModelParams& params,
             BendingTerm::Assembly assembly = BendingTerm::Assembly::PerHinge);

  const Mesh& mesh() const { return mesh_; }
  const ModelParams& params() const { return params_; }
  Index num_nodes() const { return mesh_.num_nodes(); }
  Index num_dofs() const { return 3 * mesh_.num_nodes(); }
  Index num_hinges() const { return mesh_.num_hinges(); }

  /// A flat state at the reference positions, at rest, with no plastic deformation.
  State rest_state() const;

  void add_term(std::shared_ptr<ForceTerm> term, TermKind kind);
  void remove_term(const ForceTerm* term);
  /// Recomputes the pattern from all terms' coupled pairs if it changed; returns true if so.
  bool rebuild_pattern();
  const BlockPattern& pattern() const { return pattern_; }
  /// Counts the pattern's rebuilds: whoever keeps slots into it (ReducedNewton) compares this
  /// with the value at its own bind, whoever called rebuild_pattern().
  std::uint64_t pattern_serial() const { return pattern_serial_; }

  Energies energies(const State& s) const;  ///< kinetic energy uses params().mass
  /// Total force F(x, v, p) (3n), overwriting f.
  void forces(const State& s, VecX& f) const;
  /// Hx, Hv on the pattern; Hp (3n x n_hinges) when with_hp.
  void jacobians(const State& s, Jacobians& J, bool with_hp) const;

  const BendingTerm& bending() const { return *bending_; }

  struct Entry {
    std::shared_ptr<ForceTerm> term;
    TermKind kind;
    bool bound = false;             ///< bind() called on the current pattern
    std::uint64_t bound_version = 0;  ///< pattern_version() at the last bind()
    std::uint64_t version = ~0ULL;  ///< pattern_version() when the pattern was built
  };
  const std::vector<Entry>& terms() const { return terms_; }

 private:
  Mesh mesh_;
  ModelParams params_;
  std::shared_ptr<BendingTerm> bending_;
  std::vector<Entry> terms_;
  BlockPattern pattern_;
  std::vector<std::pair<Index, Index>> pairs_;  // the pairs the pattern was built from
  bool terms_changed_ = true;
  std::uint64_t pattern_serial_ = 0;
};

}  // namespace crumple
