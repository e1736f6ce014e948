// Config look-ups; see config_params.hpp.
#include "analysis/run/config_params.hpp"

#include <yaml-cpp/yaml.h>

namespace crumple::analysis {

std::optional<double> compaction_from_config(const std::string& yaml_text) {
  if (yaml_text.empty()) return std::nullopt;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    const YAML::Node stages = root["protocol"]["stages"];
    if (!stages || !stages.IsSequence()) return std::nullopt;
    for (const auto& s : stages)
      if (s["type"] && s["type"].as<std::string>() == "compress" && s["compaction"])
        return s["compaction"].as<double>();
  } catch (const YAML::Exception&) {
    // A config the analysis cannot read only costs the c1/c2 conversion, not the analysis.
  }
  return std::nullopt;
}

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

}  // namespace crumple::analysis
