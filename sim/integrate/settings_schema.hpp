// The integrator section of the configuration (keys of IntegratorSettings, settings.hpp): each
// key once with its unit, range, one-line meaning and relations (sim/core/schema.hpp). The
// config reader, validate(IntegratorSettings), --list-keys and docs/CONFIG.md read it.
#pragma once

#include "sim/core/schema.hpp"

namespace crumple {

const schema::Section& integrator_schema();

}  // namespace crumple
