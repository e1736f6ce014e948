// Per-stage crease accounting; see stage_accounting.hpp.
#include "analysis/creases/stage_accounting.hpp"

#include "analysis/creases/crease_edges.hpp"

#include <stdexcept>

namespace crumple::analysis {

std::vector<StageCreases> account_stages(const MeshData& mesh,
                                         const std::vector<const StageEndData*>& stages,
                                         const std::vector<char>& cycle_end,
                                         const std::vector<char>& previous_end, double threshold,
                                         const CreaseBand* band) {
  const std::size_t h = mesh.hinge_edge.size();
  if (cycle_end.size() != h || (!previous_end.empty() && previous_end.size() != h))
    throw std::invalid_argument("account_stages: one flag per hinge expected");
  std::vector<std::vector<char>> creased;
  std::vector<StageCreases> out;
  for (const StageEndData* s : stages) {
    if (s->p.size() != h) throw std::invalid_argument("account_stages: p has the wrong size");
    creased.push_back(select_creases(s->p, threshold, band));
    StageCreases r;
    r.index = s->stage_index;
    r.stage = s->stage;
    r.t = s->t;
    for (char f : creased.back()) r.crease_edges += f;
    r.crease_length = crease_length(mesh, creased.back());
    const std::vector<char>& before =
        creased.size() > 1 ? creased[creased.size() - 2] : previous_end;
    if (!before.empty())
      for (std::size_t i = 0; i < h; ++i)
        if (before[i] && !creased.back()[i])
          r.lost_length += mesh.rest_lengths[static_cast<std::size_t>(mesh.hinge_edge[i])];
    out.push_back(std::move(r));
  }
  if (out.empty()) return out;
  const std::size_t K = out.size();
  for (std::size_t i = 0; i < h; ++i) {
    const bool is_new = cycle_end[i] && (previous_end.empty() || !previous_end[i]);
    if (!is_new || !creased[K - 1][i]) continue;  // not new, or not creased at the last stage end
    std::size_t k = K - 1;
    while (k > 0 && creased[k - 1][i]) --k;  // back to the start of its unbroken creased run
    out[k].new_length += mesh.rest_lengths[static_cast<std::size_t>(mesh.hinge_edge[i])];
  }
  return out;
}

std::optional<double> share_after_last(const std::vector<StageCreases>& stages,
                                       const std::string& stage_type, double cycle_new_length) {
  if (stages.empty() || !(cycle_new_length > 0)) return std::nullopt;
  std::optional<std::size_t> last;
  for (std::size_t k = 0; k < stages.size(); ++k)
    if (stages[k].stage == stage_type) last = k;
  if (!last) return std::nullopt;
  double after = 0.0;
  for (std::size_t k = *last + 1; k < stages.size(); ++k) after += stages[k].new_length;
  return after / cycle_new_length;
}

}  // namespace crumple::analysis
