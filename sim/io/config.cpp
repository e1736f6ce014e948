// Configuration loading with file:line:column errors, --set overrides and the resolved YAML
// (config.hpp). What the keys are is not written here: the reader and the emitter walk the
// schema (config_schema.cpp), so a key added there is read, checked, printed and documented.
#include "sim/io/config.hpp"

#include "sim/core/errors.hpp"
#include "sim/io/config_schema.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace crumple {

namespace {

struct Context {
  std::string file;
  std::map<std::string, std::string> overrides;  // dotted key -> "key=value" as given
  std::map<std::string, std::string> stage_sets;  // "protocol.stages[k].key" -> "--set ..."
  std::map<std::string, std::string>* origins = nullptr;  // Params::origins being filled

  /// The --set argument that gave `dotted`, a key below it or a section above it; empty: none.
  std::string override_of(const std::string& dotted) const {
    for (const auto& [key, spec] : overrides)
      if (key == dotted || dotted.rfind(key + ".", 0) == 0 || key.rfind(dotted + ".", 0) == 0)
        return spec;
    return {};
  }
  std::string where(const YAML::Node& n, const std::string& dotted) const {
    if (const std::string spec = override_of(dotted); !spec.empty()) return "--set " + spec;
    std::ostringstream os;
    os << file << ':' << n.Mark().line + 1 << ':' << n.Mark().column + 1;
    return os.str();
  }
  [[noreturn]] void fail(const YAML::Node& n, const std::string& dotted,
                         const std::string& what) const {
    throw InputError(where(n, dotted) + ": " + dotted + ": " + what);
  }
};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string scalar_text(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "nothing";
}

/// Reads one section of the config into its struct, key by key as the schema declares it;
/// records where each given key was set (Params::origins).
class SectionReader {
 public:
  SectionReader(const YAML::Node& root, const schema::Section& section, void* values,
                const Context& ctx)
      : section_(section), values_(values), ctx_(ctx), node_(root[section.name]) {
    // (a copy of the handle: assigning a missing key through a reference would throw)
    if (!node_.IsDefined() || node_.IsNull()) return;
    if (!node_.IsMap())
      ctx_.fail(node_, section_.name, "expected a map of keys, got " + scalar_text(node_));
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string key = it->first.Scalar();
      if (section_.find(key)) continue;
      for (const auto& [retired, why] : retired_keys())
        if (retired == dotted(key)) ctx_.fail(it->first, dotted(key), why);
      ctx_.fail(it->first, dotted(key), "unknown key (valid: " + join(section_.names()) + ")");
    }
  }

  /// Every key, then the groups and relations between them.
  void read_all() {
    for (const auto& k : section_.keys) read(k);
    check_groups();
    check_relations();
  }

  YAML::Node get(const std::string& key) const {
    if (!node_.IsDefined() || node_.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node n = node_[key];
    if (!n.IsDefined() || n.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    if (ctx_.origins) (*ctx_.origins)[dotted(key)] = ctx_.where(n, dotted(key));
    return n;
  }
  std::string dotted(const std::string& key) const { return section_.name + "." + key; }

 private:
  void read(const schema::Key& k) {
    const YAML::Node n = get(k.name);
    if (!n || k.kind == schema::Kind::List) return;  // lists are read by their owner
    switch (k.kind) {
      case schema::Kind::Real:
      case schema::Kind::Integer: {
        double v;
        if (!parse(n, v) || (k.kind == schema::Kind::Integer && v != std::floor(v)))
          ctx_.fail(n, dotted(k.name),
                    std::string(k.kind == schema::Kind::Integer ? "expected a whole number, got "
                                                                : "expected a number, got ") +
                        scalar_text(n));
        if (const std::string e = k.range_error(v, n.Scalar()); !e.empty())
          ctx_.fail(n, dotted(k.name), e);
        k.set_number(values_, v);
        break;
      }
      case schema::Kind::Word: {
        if (!n.IsScalar()) ctx_.fail(n, dotted(k.name), "expected a word, got " + scalar_text(n));
        bool ok = false;
        for (const auto& c : k.choices) ok = ok || c == n.Scalar();
        if (!ok)
          ctx_.fail(n, dotted(k.name),
                    "unknown value '" + n.Scalar() + "' (valid: " + join(k.choices) + ")");
        k.set_word(values_, n.Scalar());
        break;
      }
      case schema::Kind::Flag: {
        bool b = false;
        try {
          b = n.as<bool>();
        } catch (const YAML::Exception&) {
          ctx_.fail(n, dotted(k.name), "expected true or false, got " + scalar_text(n));
        }
        k.set_number(values_, b ? 1 : 0);
        break;
      }
      case schema::Kind::List: break;
    }
  }

  /// Keys given together or not at all (material ks, kb, mass): names the first one missing.
  void check_groups() const {
    const auto& group = section_.all_or_none;
    if (group.empty()) return;
    int given = 0;
    std::string missing, all;
    for (std::size_t i = 0; i < group.size(); ++i) {
      const bool set = section_.find(group[i])->get_number(values_) != 0;
      given += set;
      if (!set && missing.empty()) missing = group[i];
      all += (i == 0 ? "" : i + 1 == group.size() ? " and " : ", ") + group[i];
    }
    if (given != 0 && given != static_cast<int>(group.size()))
      ctx_.fail(node_, dotted(missing), all + " are given together or not at all");
  }

  /// The error names a key of the pair that a --set override gave, else the one the relation
  /// blames if the file sets it (its line), else the other (the defaults satisfy every
  /// relation, so one of the two is always set when it fails).
  void check_relations() const {
    for (const auto& r : section_.relations) {
      const double a = section_.find(r.lhs)->get_number(values_);
      const double b = section_.find(r.rhs)->get_number(values_);
      if (r.holds(a, b)) continue;
      const std::string first = r.blame.empty() ? r.lhs : r.blame;
      const std::string second = first == r.lhs ? r.rhs : r.lhs;
      const auto by_set = [&](const std::string& k) { return ctx_.overrides.count(dotted(k)) > 0; };
      const auto given = [&](const std::string& k) { return bool(get(k)); };
      const std::string& key = by_set(first)    ? first
                               : by_set(second) ? second
                               : given(first)   ? first
                               : given(second)  ? second
                                                : first;
      const YAML::Node n = get(key);
      ctx_.fail(n ? n : node_, dotted(key),
                "need " + dotted(r.lhs) + " " + r.op + " " + dotted(r.rhs) + ", got " + num(a) +
                    (r.op == "<" ? " >= " : " > ") + num(b));
    }
  }

  static std::string num(double v) {  // enough digits that two values in a message differ
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
  }
  static bool parse(const YAML::Node& n, double& v) {
    if (!n.IsScalar()) return false;
    try {
      v = n.as<double>();
      return std::isfinite(v);
    } catch (const YAML::Exception&) {
      return false;
    }
  }
  const schema::Section& section_;
  void* values_;
  const Context& ctx_;
  YAML::Node node_;
};

std::string mark_of(const std::string& file, const YAML::Mark& m) {
  return file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

/// yaml-cpp keeps the first of two equal keys without a word, and takes any node as a key:
/// both are refused here, over the whole tree, with the places of both keys.
void check_keys(const YAML::Node& n, const std::string& file, const std::string& path) {
  if (n.IsMap()) {
    std::map<std::string, YAML::Mark> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node k = it->first;  // a copy: `it->` is a proxy that dies here
      if (!k.IsScalar())
        throw InputError(mark_of(file, k.Mark()) + ": " + (path.empty() ? "" : path + ": ") +
                         "a key must be a plain word, got " + scalar_text(k));
      const std::string dotted = path.empty() ? k.Scalar() : path + "." + k.Scalar();
      const auto [at, fresh] = seen.emplace(k.Scalar(), k.Mark());
      if (!fresh)
        throw InputError(mark_of(file, k.Mark()) + ": " + dotted + ": duplicate key (first at " +
                         mark_of(file, at->second) + ")");
      check_keys(it->second, file, dotted);
    }
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i)
      check_keys(n[i], file, path + "[" + std::to_string(i) + "]");
  }
}

/// `--set protocol.stages.SEL.KEY=VALUE`: one parameter of one stage of the list (the file's or
/// an earlier --set's), SEL a stage type that appears once or a 0-based index. The stage
/// registry validates the value later and names this argument (ProtocolParams::stage_sets).
void apply_stage_override(YAML::Node& root, const std::vector<std::string>& parts,
                          const YAML::Node& value, const std::string& spec, Context& ctx) {
  const auto fail = [&](const std::string& what) { throw InputError("--set " + spec + ": " + what); };
  if (parts.size() != 4)
    fail("a stage parameter is protocol.stages.TYPE.KEY=VALUE or protocol.stages.INDEX.KEY=VALUE");
  YAML::Node stages = root["protocol"]["stages"];
  if (!stages.IsDefined() || !stages.IsSequence() || stages.size() == 0)
    fail("the protocol has no stage list to set a parameter in");
  const std::string& sel = parts[2];
  const std::string& key = parts[3];
  std::vector<std::size_t> found;
  std::string types;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const YAML::Node t = stages[k].IsMap() ? stages[k]["type"] : YAML::Node();
    const std::string name = t.IsDefined() && t.IsScalar() ? t.Scalar() : "?";
    types += (types.empty() ? "" : ", ") + std::to_string(k) + ": " + name;
    if (name == sel) found.push_back(k);
  }
  std::size_t k = 0;
  if (!sel.empty() && sel.find_first_not_of("0123456789") == std::string::npos) {
    k = sel.size() <= 6 ? std::stoul(sel) : stages.size();
    if (k >= stages.size())
      fail("stage index " + sel + " out of range (the stages are " + types + ")");
  } else if (found.size() == 1) {
    k = found[0];
  } else if (found.empty()) {
    fail("no stage of type '" + sel + "' in the protocol (the stages are " + types + ")");
  } else {
    std::string at;
    for (auto i : found) at += (at.empty() ? "" : ", ") + std::to_string(i);
    fail("the protocol has " + std::to_string(found.size()) + " " + sel + " stages (" + at +
         "): name one by its index, e.g. protocol.stages." + std::to_string(found[0]) + "." +
         key + "=...");
  }
  if (key == "type") fail("a stage's type cannot be set alone; give the whole protocol.stages list");
  if (!stages[k].IsMap()) fail("stage " + std::to_string(k) + " is not a map");
  YAML::Node stage = stages[k];
  stage[key] = value;
  ctx.stage_sets["protocol.stages[" + std::to_string(k) + "]." + key] = "--set " + spec;
}

void apply_override(YAML::Node& root, const std::string& spec, Context& ctx) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + spec + ": expected dotted.key=value");
  const std::string key = spec.substr(0, eq), value = spec.substr(eq + 1);
  // An empty value would read as YAML null, which every key takes as "use the default".
  if (value.find_first_not_of(" \t") == std::string::npos)
    throw InputError("--set " + spec + ": empty value (give " + key + "=VALUE)");
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  if (parts.size() < 2) throw InputError("--set " + spec + ": expected section.key=value");
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + spec + ": cannot parse the value: " + e.msg);
  }
  check_keys(parsed, "--set " + spec, key);
  if (parts.size() > 2 && parts[0] == "protocol" && parts[1] == "stages")
    return apply_stage_override(root, parts, parsed, spec, ctx);
  // Walk down with fresh handles (yaml-cpp nodes are references; assignment would alias).
  std::vector<YAML::Node> path{root};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node next = path.back()[parts[i]];
    if (next.IsDefined() && !next.IsNull() && !next.IsMap())
      throw InputError("--set " + spec + ": " + parts[i] + " is not a section");
    path.push_back(next);
  }
  path.back()[parts.back()] = parsed;
  ctx.overrides[key] = spec;
  if (key == "protocol.stages") ctx.stage_sets.clear();  // a new list: earlier stage sets are gone
}

Params parse(YAML::Node root, Context& ctx) {
  Params p;
  p.file = ctx.file;
  if (root.IsNull() || !root.IsDefined()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap())
    throw InputError(ctx.file + ":1:1: the configuration must be a map of sections");
  std::vector<std::string> sections;
  for (const auto& cs : config_schema()) sections.push_back(cs.section->name);
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.Scalar();
    bool ok = false;
    for (const auto& s : sections) ok = ok || s == key;
    if (!ok) ctx.fail(it->first, key, "unknown section (valid: " + join(sections) + ")");
  }
  for (const auto& cs : config_schema()) {
    SectionReader reader(root, *cs.section, cs.of(p), ctx);
    reader.read_all();
    if (cs.section->name != "protocol") continue;
    // The stage list: kept as YAML, validated by the stage registry (it knows the stage types).
    const YAML::Node stages = reader.get("stages");
    if (stages && !stages.IsSequence())
      ctx.fail(stages, "protocol.stages", "expected a list of stages, got " + scalar_text(stages));
    p.protocol.stages = stages ? stages : YAML::Node(YAML::NodeType::Sequence);
  }
  return p;
}

/// The schema's integrator.plastic_c0, which material.yield_radius or yield_angle sets.
const schema::Key* yield_derived_key() {
  static const schema::Key* key = [] {
    for (const auto& cs : config_schema())
      if (cs.section->name == "integrator") return cs.section->find("plastic_c0");
    return static_cast<const schema::Key*>(nullptr);
  }();
  return key;
}

/// material.yield_radius and material.yield_angle each set integrator.plastic_c0; two of the
/// three given is a contradiction, reported at the later key with the place of the first.
void check_yield_given_once(const Params& p) {
  const auto given = [&](const char* key) { return p.origins.count(key) > 0; };
  const auto refuse = [&](const std::string& key, const std::string& by, const char* how) {
    throw InputError(p.where(key) + ": given together with " + by + " (" + p.origins.at(by) + ")" +
                     how + "; give one of the two");
  };
  const bool radius = p.material.yield_radius > 0, angle = p.material.yield_angle > 0;
  if (radius && angle)
    refuse("material.yield_angle", "material.yield_radius", ": two statements of the sheet's yield");
  if (!given("integrator.plastic_c0")) return;
  if (radius) refuse("integrator.plastic_c0", "material.yield_radius", ", which sets it on each mesh");
  if (angle) refuse("integrator.plastic_c0", "material.yield_angle", ", which sets it on every mesh");
}

Params load_from(const std::string& text, const std::string& name,
                 const std::vector<std::string>& overrides) {
  Context ctx;
  ctx.file = name;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(name + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  check_keys(root, name, "");
  for (const auto& o : overrides) apply_override(root, o, ctx);
  std::map<std::string, std::string> origins;
  ctx.origins = &origins;
  Params p = parse(root, ctx);
  p.origins = std::move(origins);
  // Stage parameters are read later by the stage registry: it names the place of a stage given
  // by --set after the --set argument itself.
  if (const std::string spec = ctx.override_of("protocol.stages"); !spec.empty())
    p.protocol.stages_source = "--set " + spec;
  else
    p.protocol.stages_source = name;
  p.protocol.stage_sets = std::move(ctx.stage_sets);
  check_yield_given_once(p);
  return p;
}

}  // namespace

Params load_config(const std::string& path, const std::vector<std::string>& overrides) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (fs::is_directory(status))
    throw InputError(path + ": is a directory, not a configuration file");
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path + ": not a regular file (a device, pipe or socket), not a configuration file");
  // A configuration is a page of YAML; a huge file is a mistake (and would be read whole).
  constexpr std::uintmax_t kMaxBytes = 1 << 20;
  if (fs::is_regular_file(status) && fs::file_size(path, ec) > kMaxBytes)
    throw InputError(path + ": " + std::to_string(fs::file_size(path, ec)) +
                     " bytes: too large for a configuration file (at most 1 MiB)");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the configuration file");
  std::stringstream ss;
  ss << in.rdbuf();
  return load_from(ss.str(), path, overrides);
}

Params load_config_text(const std::string& text, const std::string& name,
                        const std::vector<std::string>& overrides) {
  return load_from(text, name, overrides);
}

Params load_stored_config(const std::string& text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException&) {
    return load_from(text, name, {});  // reports the syntax error with its place
  }
  bool dropped = false;
  const auto drop = [&](const std::string& dotted) {
    const auto dot = dotted.find('.');
    YAML::Node section = root[dotted.substr(0, dot)];
    if (section.IsMap() && section[dotted.substr(dot + 1)])
      dropped = section.remove(dotted.substr(dot + 1)) || dropped;
  };
  for (const auto& [dotted, why] : retired_keys()) drop(dotted);
  // A run with a yield radius or angle stores the plastic_c0 it derived, for readers; as input
  // the two contradict each other (check_yield_given_once), so the derived one goes.
  if (root.IsMap() && root["material"].IsMap() &&
      (root["material"]["yield_radius"] || root["material"]["yield_angle"]))
    drop("integrator.plastic_c0");
  if (!dropped) return load_from(text, name, {});
  YAML::Emitter e;
  e.SetDoublePrecision(17);
  e << root;
  return load_from(e.c_str(), name, {});
}

std::string resolved_yaml(const Params& p) {
  YAML::Emitter e;
  e.SetDoublePrecision(17);
  e << YAML::BeginMap;
  for (const auto& cs : config_schema()) {
    const void* values = cs.of_const(p);
    e << YAML::Key << cs.section->name << YAML::Value << YAML::BeginMap;
    for (const auto& k : cs.section->keys) {
      if (k.kind == schema::Kind::List) {
        e << YAML::Key << k.name << YAML::Value << p.protocol.stages;
        continue;
      }
      if (k.zero_is_unset && k.get_number(values) == 0) continue;
      // With a yield radius, plastic_c0 is known only on a mesh: a run stores the value it
      // derived (Params::c0_from_mesh); a configuration not yet on a mesh leaves it out, so that
      // it reads back as it was given (a yield angle is treated alike).
      if (&k == yield_derived_key() && p.material.states_yield() && !p.c0_from_mesh) continue;
      e << YAML::Key << k.name << YAML::Value;
      switch (k.kind) {
        case schema::Kind::Real: e << k.get_number(values); break;
        case schema::Kind::Integer: e << static_cast<long long>(k.get_number(values)); break;
        case schema::Kind::Flag: e << (k.get_number(values) != 0); break;
        case schema::Kind::Word: e << k.get_word(values); break;
        case schema::Kind::List: break;
      }
    }
    e << YAML::EndMap;
  }
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

}  // namespace crumple
