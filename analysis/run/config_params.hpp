// Values the analysis takes from the run's resolved YAML config (/config): the yield curvature
// c0 that sets the crease threshold. (The compaction ratio is not looked for here: the run file
// records it per cycle, run/compaction.hpp.)
#pragma once

#include <optional>
#include <string>

namespace crumple::analysis {

/// The simulator's default yield curvature (integrator.plastic_c0 in docs/CONFIG.md), used when
/// the config does not give one.
inline constexpr double kDefaultPlasticC0 = 0.1;

/// integrator.plastic_c0; nullopt when the text is empty, not YAML, or has no such key (the
/// caller then uses kDefaultPlasticC0, as the simulator did).
std::optional<double> plastic_c0_from_config(const std::string& yaml_text);

/// output.crease_angle in degrees when the config states one (> 0), else nullopt: the
/// protocol's own crease definition, which the analysis takes as its default threshold.
std::optional<double> crease_angle_from_config(const std::string& yaml_text);

}  // namespace crumple::analysis
