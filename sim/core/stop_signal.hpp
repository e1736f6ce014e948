// Stop requests by signal: SIGTERM (what a cluster scheduler sends at a job's time limit) and
// SIGINT (Ctrl-C) set a flag instead of killing the process, so that the protocol runner can
// finish the chunk of steps it is in, write a checkpoint and exit 128 + the signal number
// (README.md, "Running the simulator"). A second signal of either kind while the first is
// being honoured kills the process as usual (the handlers are one-shot).
#pragma once

#include <csignal>

namespace crumple {

namespace detail {
inline volatile std::sig_atomic_t g_stop_signal = 0;
inline void on_stop_signal(int signo) { g_stop_signal = signo; }
}  // namespace detail

/// Installs the one-shot handlers for SIGTERM and SIGINT.
inline void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = detail::on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // the next signal takes the default action: a stuck run can be killed
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
}

/// The signal that asked the run to stop, or 0.
inline int stop_requested() { return detail::g_stop_signal; }

}  // namespace crumple
