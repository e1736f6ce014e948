// Stage types registered by name (docs/MODEL.md §11.1). Each built-in type registers itself in
// its own file, protocols/stages/NAME.cpp, with CRUMPLE_REGISTER_STAGE; the build compiles every
// file in that folder, so adding a stage type is one C++ file and no other edit.
// An unknown name is rejected with the sorted list of valid names.
#pragma once

#include "protocols/stage.hpp"
#include "protocols/stage_args.hpp"

#include <functional>
#include <map>
#include <vector>

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

/// A function returning a stage type's description; called once, by StageRegistry::builtin().
using StageTypeFactory = StageType (*)();

/// The factories registered with CRUMPLE_REGISTER_STAGE, in static-initialisation order, which
/// is unspecified across files; the registry sorts the types by name, so nothing depends on it.
const std::vector<StageTypeFactory>& registered_stage_types();

/// Appends its factory to registered_stage_types() when constructed (before main).
struct StageRegistrar {
  explicit StageRegistrar(StageTypeFactory factory);
};

}  // namespace crumple

/// Registers a built-in stage type from its own file: `CRUMPLE_REGISTER_STAGE(roll_stage_type);`
/// at namespace scope, after the function. The factory runs only when the registry is first
/// used, so no stage description is built during static initialisation. One per file (a second
/// registrar's name would clash); test_stage_files ties each file NAME.cpp to the type NAME.
/// The registrar only runs if its object file is linked: see protocols/CMakeLists.txt.
#define CRUMPLE_REGISTER_STAGE(factory) \
  static const ::crumple::StageRegistrar crumple_stage_registrar(&factory)
