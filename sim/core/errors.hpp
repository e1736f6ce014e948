// Exceptions that map to the exit codes users and scripts rely on (README.md, "Running the
// simulator"):
//   InputError       -> 2  bad config, arguments or input file; nothing is written
//   NumericalFailure -> 3  the integration cannot continue; a checkpoint is kept
//   Interrupted      -> 128 + signal  SIGTERM or SIGINT: stopped after a checkpoint
//   OutputError      -> 1  an output file could not be written (disk full, permissions); the
//                          last checkpoint is kept and nothing is left under a final name
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

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The run was asked to stop (sim/core/stop_signal.hpp) and has written its checkpoint.
struct Interrupted : std::runtime_error {
  Interrupted(int signo, const std::string& what) : std::runtime_error(what), signal(signo) {}
  int signal;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNumerical = 3;

}  // namespace crumple
