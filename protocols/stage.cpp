// Stage helpers shared by every stage type (stage.hpp).
#include "protocols/stage.hpp"

#include "sim/model/rigid_motion.hpp"

namespace crumple {

double StageContext::max_deformation_speed() const {
  return max_speed_relative_to_rigid(state->x, state->v);
}

double StageContext::kinetic_energy() const {
  return 0.5 * sheet.mass * state->v.squaredNorm();
}

double StageContext::max_acceleration() const {
  VecX f;
  model->forces(*state, f);
  double m = 0;
  for (Index i = 0; i < f.size() / 3; ++i) m = std::max(m, node(f, i).norm());
  return m / sheet.mass;
}

void Stage::own(StageContext& ctx, std::shared_ptr<ForceTerm> term, TermKind kind) {
  ctx.model->add_term(term, kind);
  terms_.push_back(std::move(term));
}

void Stage::release_terms(StageContext& ctx) {
  for (const auto& t : terms_) ctx.model->remove_term(t.get());
  terms_.clear();
}

}  // namespace crumple
