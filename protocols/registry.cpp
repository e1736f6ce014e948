// The stage registry (registry.hpp).
#include "protocols/registry.hpp"

#include "sim/core/schema.hpp"

#include <cmath>
#include <sstream>

namespace crumple {

namespace {
// A function-local static, so it exists before the first registrar appends to it, whatever the
// order in which the stage files' static objects are constructed.
std::vector<StageTypeFactory>& factories() {
  static std::vector<StageTypeFactory> list;
  return list;
}
}  // namespace

StageRegistrar::StageRegistrar(StageTypeFactory factory) { factories().push_back(factory); }

const std::vector<StageTypeFactory>& registered_stage_types() { return factories(); }

const StageRegistry& StageRegistry::builtin() {
  static const StageRegistry reg = [] {
    StageRegistry r;
    for (StageTypeFactory f : registered_stage_types()) r.add(f());
    return r;
  }();
  return reg;
}

void StageRegistry::add(StageType type) {
  const std::string name = type.name;
  if (!types_.emplace(name, std::move(type)).second)
    throw std::logic_error("stage type registered twice: " + name);
}

const StageType* StageRegistry::find(const std::string& name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> StageRegistry::names() const {
  std::vector<std::string> v;
  for (const auto& [k, t] : types_) v.push_back(k);
  return v;
}

std::unique_ptr<Stage> StageRegistry::make(const YAML::Node& node, const std::string& file,
                                           const std::string& path, const StageSets* sets) const {
  auto mark = [&](const YAML::Node& n) {
    return file + ":" + std::to_string(n.Mark().line + 1) + ":" +
           std::to_string(n.Mark().column + 1);
  };
  if (!node.IsMap()) throw InputError(mark(node) + ": " + path + ": a stage must be a map");
  const YAML::Node t = node["type"];
  if (!t.IsDefined())
    throw InputError(mark(node) + ": " + path + ".type: missing (every stage needs a type)");
  const std::string name = t.IsScalar() ? t.Scalar() : "";
  const StageType* st = find(name);
  if (!st) {
    std::string valid;
    for (const auto& n : names()) valid += (valid.empty() ? "" : ", ") + n;
    throw InputError(mark(t) + ": " + path + ".type: unknown stage type '" + name +
                     "' (valid: " + valid + ")");
  }
  StageArgs args(node, file, path, st->params, sets);
  if (st->check) st->check(args);
  return st->make(args);
}

void StageRegistry::validate_protocol(const YAML::Node& stages, const std::string& file,
                                      const StageSets* sets) const {
  if (!stages.IsSequence() || stages.size() == 0)
    throw InputError(file + ": protocol.stages: the protocol has no stages");
  std::vector<std::string> provided;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const std::string path = "protocol.stages[" + std::to_string(k) + "]";
    make(stages[k], file, path, sets);
    const StageType& st = *find(stages[k]["type"].Scalar());
    for (const auto& need : st.needs) {
      bool ok = false;
      for (const auto& p : provided) ok = ok || p == need;
      if (ok) continue;
      std::string by;
      for (const auto& [name, t] : types_)
        for (const auto& p : t.provides)
          if (p == need) by += (by.empty() ? "" : " or ") + name;
      const YAML::Mark m = stages[k]["type"].Mark();
      throw InputError(file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1) +
                       ": " + path + ": a " + st.name + " stage needs a " + by +
                       " stage before it in the cycle (the apparatus is reset at every cycle)");
    }
    provided.insert(provided.end(), st.provides.begin(), st.provides.end());
  }
}

namespace {

/// A stage parameter's range in the notation of the config keys (sim/core/schema.hpp); 1e30
/// stands for "no bound" in the stage tables.
std::string range_text(const ParamSpec& p) {
  if (p.kind == ParamSpec::Kind::Flag) return "";
  if (p.kind == ParamSpec::Kind::Text) {
    std::string s;
    for (const auto& c : p.choices) s += (s.empty() ? "" : ", ") + c;
    return s;
  }
  schema::Key k;
  k.kind = schema::Kind::Real;
  if (std::isfinite(p.min) && std::abs(p.min) < 1e30) k.lo = p.min;
  if (std::isfinite(p.max) && std::abs(p.max) < 1e30) k.hi = p.max;
  k.lo_open = p.min_open;
  return k.range_doc();
}

std::string default_text(const ParamSpec& p) {
  if (p.fallback.empty()) return "required";
  if (p.kind != ParamSpec::Kind::Number && p.kind != ParamSpec::Kind::Numbers) return p.fallback;
  const double v = std::stod(p.fallback);
  return v >= 1e30 ? "none (1e30)" : schema::format_number(v);
}

}  // namespace

std::string StageRegistry::describe_markdown() const {
  std::ostringstream os;
  os << "<!-- keys: stages -->\n";
  for (const auto& [name, t] : types_) {
    os << "\n#### `" << name << "`\n" << t.help << ".";
    if (!t.needs.empty()) {
      os << " Needs, earlier in the cycle:";
      for (const auto& n : t.needs) os << " " << n;
      os << ".";
    }
    if (!t.provides.empty()) {
      os << " Provides:";
      for (const auto& n : t.provides) os << " " << n;
      os << ".";
    }
    os << "\n\n| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n";
    for (const auto& p : t.params) {
      const char* type = p.kind == ParamSpec::Kind::Number    ? "number"
                         : p.kind == ParamSpec::Kind::Numbers ? "number or list"
                         : p.kind == ParamSpec::Kind::Flag    ? "bool"
                                                              : "word";
      os << "| `" << p.name << "` | " << type << " | " << default_text(p) << " | " << range_text(p)
         << " | " << p.help << " |\n";
    }
  }
  os << "<!-- /keys -->\n";
  return os.str();
}

std::string StageRegistry::describe() const {
  std::ostringstream os;
  for (const auto& [name, t] : types_) {
    os << name << ": " << t.help << "\n";
    for (const auto& p : t.params) {
      os << "    " << p.name;
      os << (p.fallback.empty() ? " (required)" : " = " + default_text(p));
      if (!p.choices.empty()) {
        os << " {";
        for (std::size_t i = 0; i < p.choices.size(); ++i) os << (i ? "|" : "") << p.choices[i];
        os << "}";
      }
      os << "  " << p.help << "\n";
    }
  }
  return os.str();
}

}  // namespace crumple
