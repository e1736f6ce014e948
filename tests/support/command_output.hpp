// Runs a shell command and returns what it printed on stdout with its exit code: for tests of a
// program's --version and --help (stderr is discarded).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace crumple::testing {

inline std::string command_output(const std::string& command, int& exit_code) {
  FILE* p = popen((command + " 2>/dev/null").c_str(), "r");
  std::string text;
  char buf[512];
  while (p && std::fgets(buf, sizeof buf, p)) text += buf;
  const int status = p ? pclose(p) : -1;
  exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return text;
}

}  // namespace crumple::testing
