// Loading and printing the run configuration (docs/CONFIG.md). Every key is validated: an
// unknown key, a wrong type, an out-of-range value, an unknown choice or a YAML syntax error is
// an InputError "FILE:LINE:COLUMN: section.key: what is wrong" (1-based). `--set dotted.key=value`
// overrides are applied to the YAML before validation; errors in them name "--set key=value".
#pragma once

#include "sim/io/params.hpp"

#include <vector>

namespace crumple {

Params load_config(const std::string& path, const std::vector<std::string>& overrides = {});
/// Parses YAML text as if it were the file `name` (tests, resolved configs).
Params load_config_text(const std::string& text, const std::string& name,
                        const std::vector<std::string>& overrides = {});
/// A configuration a run file stored (its /config): keys retired since that run was written
/// (config_schema.hpp, retired_keys) are dropped, so that an older run can still be resumed.
Params load_stored_config(const std::string& text, const std::string& name);
/// The full resolved configuration, every key with its value; load_config_text of it gives
/// the same Params.
std::string resolved_yaml(const Params& p);

}  // namespace crumple
