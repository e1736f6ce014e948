// The configuration's keys as text: the listing of `crumple-sim --list-keys` and the tables of
// docs/CONFIG.md (`--list-keys --markdown`, spliced in by pipeline/docs/update_config_doc.py).
// Both are rendered from the schema (config_schema.hpp), so neither can drift from the reader.
#pragma once

#include <string>

namespace crumple {

/// Every section and key: dotted key, type, default, range, unit, meaning.
std::string config_keys_text();

/// One markdown table per section, each between `<!-- keys: SECTION -->` and `<!-- /keys -->`.
std::string config_keys_markdown();

}  // namespace crumple
