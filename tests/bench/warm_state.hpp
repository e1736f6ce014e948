// A benchmark's warm state on disk: the sheet state after a warm-up (x, v, p at t) with the node
// count and the settings it was integrated with, so a later run can start its timed intervals
// without repeating a warm-up that takes minutes (12000 nodes: about 10 min to t = 1 s).
#pragma once

#include "sim/io/h5.hpp"
#include "sim/model/state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace crumple {

inline void save_warm_state(const std::string& path, const State& s, std::int64_t nodes,
                            const std::string& description) {
  const std::string tmp = path + ".new";
  {
    H5::H5File file(tmp, H5F_ACC_TRUNC);
    H5::Group g = h5::group(file, "state");
    h5::attr(g, "t", s.t);
    h5::attr(g, "nodes", nodes);
    h5::attr(g, "description", description);
    h5::write(g, "x", std::vector<double>(s.x.data(), s.x.data() + s.x.size()));
    h5::write(g, "v", std::vector<double>(s.v.data(), s.v.data() + s.v.size()));
    h5::write(g, "p", std::vector<double>(s.p.data(), s.p.data() + s.p.size()));
  }
  std::filesystem::rename(tmp, path);
}

// load_warm_state without the checks for a missing or unreadable file.
inline std::optional<State> read_warm_state(const std::string& path, std::int64_t nodes,
                                            double t, const std::string& description,
                                            bool or_earlier) {
  H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group g = file.openGroup("state");
  const double t_file = h5::attr_double(g, "t");
  // A state saved at the end of an interval [t0, t0 + dt] carries the integrator's sum, which
  // can differ from the decimal t0 + dt a later run is given in the last bits (either way): it
  // is taken as the state at t, and its time set to t.
  const bool at_t = std::abs(t_file - t) <= 1e-12 * std::max(1.0, std::abs(t));
  if (h5::attr_int(g, "nodes") != nodes || !(at_t || (or_earlier && t_file < t)) ||
      h5::attr_string(g, "description") != description)
    return std::nullopt;
  State s;
  s.t = at_t ? t : t_file;
  const auto x = h5::read_doubles(g, "x"), v = h5::read_doubles(g, "v"), p = h5::read_doubles(g, "p");
  s.x = Eigen::Map<const VecX>(x.data(), static_cast<Eigen::Index>(x.size()));
  s.v = Eigen::Map<const VecX>(v.data(), static_cast<Eigen::Index>(v.size()));
  s.p = Eigen::Map<const VecX>(p.data(), static_cast<Eigen::Index>(p.size()));
  return s;
}

/// The state in `path` if the file exists and holds `nodes` nodes at time t (or, with
/// `or_earlier`, at any time before t: the caller warms up from there) from the setup
/// `description`; nothing otherwise (another mesh, time or setup is not an error: the caller
/// warms up afresh and overwrites the file). An unreadable file is reported on stderr and
/// treated the same way.
inline std::optional<State> load_warm_state(const std::string& path, std::int64_t nodes,
                                            double t, const std::string& description,
                                            bool or_earlier = false) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    return read_warm_state(path, nodes, t, description, or_earlier);
  } catch (const H5::Exception& e) {
    std::fprintf(stderr, "%s: not a readable warm state (%s)\n", path.c_str(), e.getCDetailMsg());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: not a readable warm state (%s)\n", path.c_str(), e.what());
  }
  return std::nullopt;
}

}  // namespace crumple
