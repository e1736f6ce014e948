// Exceptions that map to the exit codes users and scripts rely on (README.md, "Running the
// simulator"):
//   InputError       -> 2  bad config, arguments or input file; nothing is written
//   NumericalFailure -> 3  the integration cannot continue; a checkpoint is kept
// anything else      -> 1
#pragma once

#include <stdexcept>
#include <string>

namespace crumple {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNumerical = 3;

}  // namespace crumple
