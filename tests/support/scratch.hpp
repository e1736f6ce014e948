// Scratch paths for tests: under the system's temporary folder and named with the process id, so
// that two test runs at once (two checkouts, CI beside a developer) never share a file.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace crumple::testing {

inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("crumple_" + std::to_string(::getpid()) + "_" + name);
}

/// A scratch folder made on construction and removed with everything in it on destruction.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& name) : path(scratch_path(name)) {
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

}  // namespace crumple::testing
