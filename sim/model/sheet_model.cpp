// The sheet model: all terms on one mesh, assembled on one pattern (sheet_model.hpp).
#include "sim/model/sheet_model.hpp"

#include "sim/model/area_barrier.hpp"
#include "sim/model/damping.hpp"
#include "sim/model/springs.hpp"

#include <algorithm>

namespace crumple {

SheetModel::SheetModel(const Mesh& mesh, const ModelParams& params, BendingTerm::Assembly assembly)
    : mesh_(mesh), params_(params) {
  // Terms keep a pointer to mesh_, which lives as long as the model (the model is not copyable
  // in practice: copying would leave the terms pointing at the old mesh).
  bending_ = std::make_shared<BendingTerm>(mesh_, params_.kb, assembly);
  add_term(std::make_shared<SpringTerm>(mesh_, params_.ks), TermKind::Stretch);
  add_term(bending_, TermKind::Bend);
  if (params_.area_barrier)
    add_term(std::make_shared<AreaBarrierTerm>(mesh_, params_.ks), TermKind::Stretch);
  if (params_.b_iso != 0.0)
    add_term(std::make_shared<DragTerm>(mesh_.num_nodes(), params_.b_iso), TermKind::Dissipative);
  if (params_.b_int != 0.0)
    add_term(std::make_shared<InternalDampingTerm>(mesh_, params_.b_int), TermKind::Dissipative);
  rebuild_pattern();
}

State SheetModel::rest_state() const {
  State s;
  s.x = mesh_.ref_flat();
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(mesh_.num_hinges());
  return s;
}

void SheetModel::add_term(std::shared_ptr<ForceTerm> term, TermKind kind) {
  terms_.push_back({std::move(term), kind});
  terms_changed_ = true;
}

void SheetModel::remove_term(const ForceTerm* term) {
  std::erase_if(terms_, [&](const Entry& e) { return e.term.get() == term; });
  terms_changed_ = true;
}

bool SheetModel::rebuild_pattern() {
  bool stale = terms_changed_;
  for (const auto& e : terms_) stale = stale || e.version != e.term->pattern_version();
  bool changed = false;
  if (stale) {
    std::vector<std::pair<Index, Index>> pairs;
    for (auto& e : terms_) {
      e.term->coupled_pairs(pairs);
      e.version = e.term->pattern_version();
    }
    for (auto& [i, j] : pairs)
      if (i > j) std::swap(i, j);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    changed = pairs != pairs_ || pattern_.num_nodes() != mesh_.num_nodes();
    if (changed) {
      pattern_ = BlockPattern(mesh_.num_nodes(), pairs);
      ++pattern_serial_;
      pairs_ = std::move(pairs);
      for (auto& e : terms_) e.bound = false;
    }
    terms_changed_ = false;
  }
  for (auto& e : terms_)
    if (!e.bound || e.bound_version != e.term->pattern_version()) {
      // A term whose stencil changed rebinds even when the node-pair set (and so the pattern)
      // stayed the same: its own element list is new.
      e.term->bind(pattern_);
      e.bound = true;
      e.bound_version = e.term->pattern_version();
    }
  return changed;
}

Energies SheetModel::energies(const State& s) const {
  Energies en;
  for (const auto& e : terms_) {
    const double v = e.term->energy(s);
    switch (e.kind) {
      case TermKind::Stretch: en.stretch += v; break;
      case TermKind::Bend: en.bend += v; break;
      case TermKind::Contact: en.contact += v; break;
      case TermKind::External: en.external += v; break;
      case TermKind::Dissipative: break;
    }
  }
  en.kinetic = 0.5 * params_.mass * s.v.squaredNorm();
  return en;
}

void SheetModel::forces(const State& s, VecX& f) const {
  f.setZero(num_dofs());
  for (const auto& e : terms_) e.term->add_force(s, f);
}

void SheetModel::jacobians(const State& s, Jacobians& J, bool with_hp) const {
  J.reset(pattern_);
  if (with_hp)
    J.Hp = SpMatCol(num_dofs(), num_hinges());
  else
    J.Hp = SpMatCol();
  for (const auto& e : terms_) e.term->add_jacobians(s, J);
}

}  // namespace crumple
