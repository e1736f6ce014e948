// Validated parameters of one stage, read from its YAML map with yaml-cpp's marks so that every
// error names the file, line, column and key (docs/CONFIG.md; exit code 2 via InputError).
//
// The parameters a stage type accepts are declared once, as ParamSpecs in its registration;
// StageArgs rejects unknown keys (listing the valid ones), missing required keys, wrong types
// and values out of range before the stage is built.
#pragma once

#include "sim/core/errors.hpp"

#include <yaml-cpp/yaml.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace crumple {

struct ParamSpec {
  /// Numbers: a number, or a list of numbers (one per cycle, say), each checked against the
  /// range; read with StageArgs::numbers.
  enum class Kind { Number, Text, Flag, Numbers };
  std::string name;
  Kind kind = Kind::Number;
  std::string fallback;  ///< default as text; empty: the parameter is required
  std::string help;
  double min = -std::numeric_limits<double>::infinity();  ///< numbers: allowed range
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< true: value must be > min (not >=)
  std::vector<std::string> choices;  ///< text: allowed values (empty: any)
};

/// Stage parameters given on the command line: "protocol.stages[k].KEY" -> "--set ..." as
/// given (ProtocolParams::stage_sets); messages about them name the argument, not a file line.
using StageSets = std::map<std::string, std::string>;

class StageArgs {
 public:
  /// node: the stage's map (with its `type` key); file: the config's path for messages;
  /// path: the dotted key of the stage, e.g. "protocol.stages[2]"; sets: which of its keys a
  /// --set argument gave (may be null).
  StageArgs(const YAML::Node& node, std::string file, std::string path,
            const std::vector<ParamSpec>& specs, const StageSets* sets = nullptr);

  double number(const std::string& key) const;
  /// A Numbers parameter: a single number gives a list of one.
  std::vector<double> numbers(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool flag(const std::string& key) const;
  /// True when the key is given in the file (not defaulted).
  bool given(const std::string& key) const;

  /// "file:line:col: path.key: what" as an InputError.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  /// A relation between two parameters failed: names both places (the second in parentheses).
  [[noreturn]] void fail_both(const std::string& key, const std::string& other,
                              const std::string& what) const;
  std::string where(const std::string& key) const;

 private:
  const ParamSpec& spec(const std::string& key) const;
  /// Fails naming `key` (and the list element `index`, when >= 0) unless v is in s's range.
  void check_range(const ParamSpec& s, const std::string& key, double v, int index) const;
  YAML::Node node_;
  std::string file_, path_;
  const std::vector<ParamSpec>* specs_;
  const StageSets* sets_;
};

}  // namespace crumple
