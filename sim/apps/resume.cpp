// Resume policy (resume.hpp).
#include "sim/apps/resume.hpp"

#include "protocols/integrator_stepper.hpp"
#include "sim/io/config.hpp"
#include "sim/io/config_schema.hpp"

#include <algorithm>
#include <map>

namespace crumple {


namespace {

// One text per value whatever its YAML style (block or flow, key order): maps with sorted keys.
std::string canonical(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  if (n.IsSequence()) {
    std::string s;
    for (const auto& x : n) s += (s.empty() ? "" : ", ") + canonical(x);
    return "[" + s + "]";
  }
  if (n.IsMap()) {
    std::map<std::string, std::string> kv;
    for (auto it = n.begin(); it != n.end(); ++it) kv[it->first.Scalar()] = canonical(it->second);
    std::string s;
    for (const auto& [k, v] : kv) s += (s.empty() ? "" : ", ") + k + ": " + v;
    return "{" + s + "}";
  }
  return "~";
}

// The resolved configuration as dotted key -> value text; a list (the stages) is one value.
void flatten(const YAML::Node& n, const std::string& path, std::map<std::string, std::string>& out) {
  if (n.IsMap() && path != "protocol.stages") {
    for (auto it = n.begin(); it != n.end(); ++it)
      flatten(it->second, path.empty() ? it->first.Scalar() : path + "." + it->first.Scalar(), out);
  } else {
    out[path] = canonical(n);
  }
}

std::map<std::string, std::string> keys_of(const Params& p) {
  std::map<std::string, std::string> out;
  flatten(YAML::Load(resolved_yaml(p)), "", out);
  return out;
}

}  // namespace

std::vector<std::string> keys_added_since(const std::string& stored_text, const Params& given) {
  // A run file stores every key resolved, so a key missing from its text was added to the
  // program after the run started: parsed, it took its default, which need not be what the
  // earlier program did (material.area_barrier is on by default; before it, nothing held a
  // triangle's area).
  std::map<std::string, std::string> present;
  flatten(YAML::Load(stored_text), "", present);
  std::vector<std::string> added;
  for (const auto& [key, value] : keys_of(given))
    if (!present.count(key))
      added.push_back(key + ": (absent: the run was started by a program without this key) -> " +
                      value);
  return added;
}

std::vector<std::string> resume_changes(const Params& stored, const Params& given,
                                        const std::string& source, bool extending) {
  const auto a = keys_of(stored), b = keys_of(given);
  std::vector<std::string> changes, refused;
  for (const auto& [key, old_value] : a) {
    const auto it = b.find(key);
    const std::string new_value = it == b.end() ? "(absent)" : it->second;
    if (new_value == old_value) continue;
    const std::string line = key + ": " + old_value + " -> " + new_value;
    const schema::Key* spec = find_key(key);
    if (extending && key == "protocol.cycles") {
      if (given.protocol.cycles > stored.protocol.cycles)
        changes.push_back(line);
      else
        refused.push_back(given.where(key) + ": " + new_value + " given, but --extend needs more "
                          "than the run's " + old_value + " cycles");
      continue;
    }
    if (spec && spec->resumable)
      changes.push_back(line);
    else
      refused.push_back(given.where(key) + ": " + old_value + " in the run, " + new_value +
                        " given");
  }
  if (extending && a.at("protocol.cycles") == b.at("protocol.cycles"))
    refused.push_back(given.where("protocol.cycles") + ": " +
                      std::to_string(given.protocol.cycles) + ", the run's own; --extend needs "
                      "more (e.g. --set protocol.cycles=" +
                      std::to_string(stored.protocol.cycles + 1) + ")");
  if (!refused.empty()) {
    const std::string flag = extending ? "--extend" : "--resume";
    std::string msg = source + ": " + flag + ": the configuration given differs from the run's "
                      "where it cannot change on " + (extending ? "extension:" : "resume:");
    for (const auto& r : refused) msg += "\n  " + r;
    msg += std::string("\n(only ") + (extending ? "protocol.cycles (upward), " : "") +
           "integrator tolerances and step limits and the output intervals may change; the "
           "run's configuration is " + source + ":/config; --force starts the run afresh)";
    throw InputError(msg);
  }
  return changes;
}

Checkpoint checkpoint_to_resume(const RunRecord& rec, const Params& p, const std::string& tmp) {
  if (!rec.checkpoint) throw InputError(tmp + ": /checkpoint: missing (not a resumable run file)");
  const Checkpoint c = load_checkpoint(*rec.checkpoint);
  const auto fail = [&](const std::string& what) { throw InputError(tmp + ": " + what); };
  if (c.cycle > p.protocol.cycles + 1)
    fail("/checkpoint@cycle: " + std::to_string(c.cycle) + " beyond the protocol's " +
         std::to_string(p.protocol.cycles) + " cycles");
  if (c.stage >= static_cast<int>(p.protocol.stages.size()))
    fail("/checkpoint@stage: " + std::to_string(c.stage) + " but the protocol has " +
         std::to_string(p.protocol.stages.size()) + " stages");
  IntegratorHistory h;
  try {
    h = unflatten_history(c.stepper);
  } catch (const InputError& e) {
    fail(std::string("/checkpoint/stepper: ") + e.what());
  }
  const Index n = rec.mesh.num_nodes(), m = rec.mesh.num_hinges();
  for (std::size_t k = 0; k < h.times.size(); ++k)
    if (h.xs[k].size() != 3 * n || h.vs[k].size() != 3 * n || h.ps[k].size() != m)
      fail("/checkpoint/stepper: history point " + std::to_string(k) +
           " does not fit the mesh (" + std::to_string(n) + " nodes, " + std::to_string(m) +
           " hinges)");
  if (h.mode != IntegrationMode::Implicit && h.mode != IntegrationMode::Explicit)
    fail("/checkpoint/stepper: unknown integration mode");
  if (!(h.h > 0) || !std::isfinite(h.h)) fail("/checkpoint/stepper: step size not positive");
  return c;
}

Checkpoint checkpoint_to_extend(RunRecord& rec, const Params& stored, const Params& given,
                                const std::string& path) {
  const auto fail = [&](const std::string& what) { throw InputError(path + ": --extend: " + what); };
  if (rec.meta.status != "complete")
    fail("/meta@status is '" + rec.meta.status + "'; only a run that completed all its cycles "
         "can be extended");
  if (!rec.checkpoint) fail("/checkpoint: missing (written by a program without it?)");
  const Checkpoint end = load_checkpoint(*rec.checkpoint);
  if (end.cycle != stored.protocol.cycles + 1 || end.stage != 0 || end.in_stage)
    fail("/checkpoint is not the end of cycle " + std::to_string(stored.protocol.cycles));
  // The runner's closing frame: added when the run's end was off the frame grid, which a longer
  // run never has there (same test and slack as ProtocolRunner::run).
  constexpr double kEps = 1e-12;
  const double t_end = end.state.t;
  if (!rec.frames.empty() && rec.frames.back().state.t == t_end &&
      t_end > end.next_frame_t - stored.output.dt + kEps)
    rec.frames.pop_back();
  return checkpoint_to_resume(rec, given, path);
}

}  // namespace crumple
