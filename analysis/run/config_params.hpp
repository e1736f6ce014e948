// Values the analysis takes from the run's resolved YAML config (/config): the compaction ratio
// of the compress stage, needed to convert the log-law fit to the experiment's c1, c2
// (statistics.md §2.3).
#pragma once

#include <optional>
#include <string>

namespace crumple::analysis {

/// `compaction` of the first stage with `type: compress` under protocol.stages; nullopt when the
/// text is empty, not YAML, or has no such stage.
std::optional<double> compaction_from_config(const std::string& yaml_text);

}  // namespace crumple::analysis
