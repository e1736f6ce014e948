// Crease selection and length; see crease_edges.hpp.
#include "analysis/creases/crease_edges.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace crumple::analysis {

std::vector<char> crease_hinges(const std::vector<double>& p, double threshold) {
  std::vector<char> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) out[i] = std::abs(p[i]) > threshold;
  return out;
}

double crease_length(const MeshData& mesh, const std::vector<char>& creased) {
  if (creased.size() != mesh.hinge_edge.size())
    throw std::invalid_argument("crease_length: one flag per hinge expected");
  double sum = 0.0;
  for (std::size_t i = 0; i < creased.size(); ++i)
    if (creased[i]) sum += mesh.rest_lengths[static_cast<std::size_t>(mesh.hinge_edge[i])];
  return sum;
}

double plastic_rotation(const MeshData& mesh, const std::vector<double>& p,
                        const std::vector<char>* only) {
  if (p.size() != mesh.hinge_edge.size() || (only && only->size() != p.size()))
    throw std::invalid_argument("plastic_rotation: one value per hinge expected");
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!only || (*only)[i])
      sum += 2.0 * std::asin(std::min(std::abs(p[i]), 2.0) / 2.0) *
             mesh.rest_lengths[static_cast<std::size_t>(mesh.hinge_edge[i])];
  return sum;
}

std::vector<char> new_creases(const std::vector<char>& now, const std::vector<char>& before) {
  std::vector<char> out(now);
  if (before.empty()) return out;
  if (before.size() != now.size()) throw std::invalid_argument("new_creases: size mismatch");
  for (std::size_t i = 0; i < now.size(); ++i) out[i] = now[i] && !before[i];
  return out;
}

}  // namespace crumple::analysis
