// Stage types registered by name (docs/MODEL.md §11.1). Built-in types are registered in
// builtin_stages.cpp, one line each; adding a stage type is one C++ file plus one line there.
// An unknown name is rejected with the sorted list of valid names.
#pragma once

#include "protocols/stage.hpp"
#include "protocols/stage_args.hpp"

#include <functional>
#include <map>

namespace crumple {

struct StageType {
  std::string name;
  std::string help;             ///< one line: what the stage models
  std::vector<ParamSpec> params;
  std::function<std::unique_ptr<Stage>(const StageArgs&)> make;
  /// Relations between the parameters (e.g. min_duration <= max_duration), checked before the
  /// stage is built; a failure calls StageArgs::fail_both. Empty: none.
  std::function<void(const StageArgs&)> check;
  /// Facts of the apparatus this stage needs from an earlier stage of the same cycle (the
  /// apparatus is reset at every cycle's start), and the facts it provides: e.g. compress needs
  /// "rolled", which roll provides. Checked over the whole protocol before anything runs.
  std::vector<std::string> needs, provides;
};

class StageRegistry {
 public:
  /// The registry with every built-in stage type.
  static const StageRegistry& builtin();

  void add(StageType type);
  const StageType* find(const std::string& name) const;
  std::vector<std::string> names() const;  ///< sorted
  /// Builds a stage from its YAML map; InputError with file:line on any problem.
  std::unique_ptr<Stage> make(const YAML::Node& node, const std::string& file,
                              const std::string& path, const StageSets* sets = nullptr) const;
  /// Builds every stage of a cycle (`stages`, a YAML list) once and checks that each one's
  /// `needs` are provided by a stage before it; InputError with file:line of the stage.
  void validate_protocol(const YAML::Node& stages, const std::string& file,
                         const StageSets* sets = nullptr) const;
  /// Every type with its parameters, for `crumple-sim --list-stages`.
  std::string describe() const;

 private:
  std::map<std::string, StageType> types_;
};

/// Registers the built-in stage types (builtin_stages.cpp).
void register_builtin_stages(StageRegistry& registry);

}  // namespace crumple
