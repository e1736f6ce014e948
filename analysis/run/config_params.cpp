// Config look-ups; see config_params.hpp.
#include "analysis/run/config_params.hpp"

#include <yaml-cpp/yaml.h>

namespace crumple::analysis {

std::optional<double> plastic_c0_from_config(const std::string& yaml_text) {
  if (yaml_text.empty()) return std::nullopt;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    const YAML::Node c0 = root["integrator"]["plastic_c0"];
    if (c0 && c0.IsScalar()) return c0.as<double>();
  } catch (const YAML::Exception&) {
    // Unreadable: the caller falls back to the default and says so in a warning.
  }
  return std::nullopt;
}

std::optional<double> crease_angle_from_config(const std::string& yaml_text) {
  if (yaml_text.empty()) return std::nullopt;
  try {
    const YAML::Node a = YAML::Load(yaml_text)["output"]["crease_angle"];
    if (a && a.IsScalar() && a.as<double>() > 0) return a.as<double>();
  } catch (const YAML::Exception&) {
    // Unreadable: no stated angle; the c0 look-up warns about the config.
  }
  return std::nullopt;
}

}  // namespace crumple::analysis
