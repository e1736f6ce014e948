// The whole configuration's schema: its sections in file order, each bound to its member of
// Params (params.hpp). Every key is declared once, here or, for the integrator, beside its
// struct (sim/integrate/settings_schema.cpp); see sim/core/schema.hpp for what a key declares.
#pragma once

#include "sim/core/schema.hpp"
#include "sim/io/params.hpp"

#include <string>
#include <vector>

namespace crumple {

struct ConfigSection {
  const schema::Section* section;
  void* (*of)(Params&);  ///< the section's struct within a Params
  const void* (*of_const)(const Params&);
};

/// mesh, material, integrator, contact, protocol, output.
const std::vector<ConfigSection>& config_schema();

/// The section and key of a dotted key ("integrator.rtol"); null when there is none.
const schema::Key* find_key(const std::string& dotted);

/// Dotted keys that may differ when a run is resumed (Key::resumable), in schema order.
std::vector<std::string> resumable_keys();

/// Keys that existed once and were removed: dotted key -> why (an older run file's stored
/// configuration may still hold them; a config that gives one is told what replaced it).
const std::vector<std::pair<std::string, std::string>>& retired_keys();

/// The value of a key in `p` as the docs and --list-keys print it ("0.1", "true", "square").
std::string value_text(const schema::Key& key, const void* section_values);

}  // namespace crumple
