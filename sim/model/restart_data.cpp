// Checked access to restart data (restart_data.hpp).
#include "sim/model/restart_data.hpp"

#include "sim/core/errors.hpp"

namespace crumple {

namespace {
template <class Map>
const typename Map::mapped_type& entry(const RestartData& d, const Map& m,
                                       const std::string& name, const char* mark) {
  const auto it = m.find(name);
  if (it == m.end()) d.fail(mark + name, "missing");
  return it->second;
}
}  // namespace

std::int64_t RestartData::integer(const std::string& name) const {
  return entry(*this, ints, name, "@");
}
double RestartData::real(const std::string& name) const { return entry(*this, reals, name, "@"); }
const std::string& RestartData::text(const std::string& name) const {
  return entry(*this, texts, name, "@");
}
const std::vector<double>& RestartData::array(const std::string& name) const {
  return entry(*this, arrays, name, "/");
}
const State& RestartData::state(const std::string& name) const {
  return entry(*this, states, name, "/");
}

void RestartData::fail(const std::string& entry, const std::string& what) const {
  throw InputError(origin + entry + ": " + what);
}

}  // namespace crumple
