// Restart data: the named numbers, texts, arrays and states one part of the program needs to
// continue a run where it stopped. Each part that has restart state (the protocol runner, the
// stages' apparatus, the integrator's history) writes its own entries and reads them back; the
// run file stores the block under /checkpoint without knowing whose entries they are, as each
// style in LAMMPS owns its restart data (docs/FILE_FORMAT.md, "/checkpoint").
//
// Reading is checked: a missing or ill-typed entry is an InputError naming where the block came
// from and the entry ("run.h5.tmp: /checkpoint@cycle: missing"), in the notation of the file
// format document: "@name" for a number or text (an HDF5 attribute), "/name" for an array or a
// state (a dataset or a group).
#pragma once

#include "sim/model/state.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace crumple {

struct RestartData {
  std::map<std::string, std::int64_t> ints;
  std::map<std::string, double> reals;
  std::map<std::string, std::string> texts;
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, State> states;
  /// Where the block was read from, for messages ("run.h5.tmp: /checkpoint").
  std::string origin = "/checkpoint";

  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  const std::vector<double>& array(const std::string& name) const;
  const State& state(const std::string& name) const;
  bool has_state(const std::string& name) const { return states.count(name) != 0; }

  /// Throws InputError "<origin><entry>: <what>"; `entry` is "@name" or "/name".
  [[noreturn]] void fail(const std::string& entry, const std::string& what) const;
};

}  // namespace crumple
