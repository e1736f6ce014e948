// Configuration loading with file:line:column errors, --set overrides and the resolved YAML
// (config.hpp). The schema is the code below: one reader call per key, with its range.
#include "sim/io/config.hpp"

#include "sim/core/errors.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace crumple {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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

class Section {
 public:
  Section(const YAML::Node& root, const std::string& name, const Context& ctx,
          std::vector<std::string> keys)
      : name_(name), ctx_(ctx), node_(root[name]) {  // copy: assigning a missing key throws
    if (!node_.IsDefined() || node_.IsNull()) return;
    if (!node_.IsMap()) ctx_.fail(node_, name, "expected a map of keys, got " + scalar_text(node_));
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string key = it->first.Scalar();
      bool known = false;
      for (const auto& k : keys) known = known || k == key;
      if (!known)
        ctx_.fail(it->first, name + "." + key, "unknown key (valid: " + join(keys) + ")");
    }
  }

  void number(const char* key, double& out, double lo, double hi, bool lo_open = false,
              bool hi_open = false) {
    const YAML::Node n = get(key);
    if (!n) return;
    double v;
    if (!parse(n, v)) ctx_.fail(n, dotted(key), "expected a number, got " + scalar_text(n));
    const bool low = lo_open ? !(v > lo) : !(v >= lo);
    const bool high = hi_open ? !(v < hi) : !(v <= hi);
    if (low || high) {
      std::ostringstream os;
      os << "must be " << (lo_open ? "> " : ">= ") << lo;
      if (std::isfinite(hi)) os << (hi_open ? " and < " : " and <= ") << hi;
      os << ", got " << n.Scalar();
      ctx_.fail(n, dotted(key), os.str());
    }
    out = v;
  }
  template <class Int>
  void integer(const char* key, Int& out, double lo, double hi) {
    const YAML::Node n = get(key);
    if (!n) return;
    double v;
    if (!parse(n, v) || v != std::floor(v))
      ctx_.fail(n, dotted(key), "expected a whole number, got " + scalar_text(n));
    if (v < lo || v > hi) {
      std::ostringstream os;
      os << "must be between " << static_cast<long long>(lo) << " and "
         << static_cast<long long>(hi) << ", got " << n.Scalar();
      ctx_.fail(n, dotted(key), os.str());
    }
    out = static_cast<Int>(v);
  }
  void text(const char* key, std::string& out, const std::vector<std::string>& choices) {
    const YAML::Node n = get(key);
    if (!n) return;
    if (!n.IsScalar()) ctx_.fail(n, dotted(key), "expected a word, got " + scalar_text(n));
    bool ok = false;
    for (const auto& c : choices) ok = ok || c == n.Scalar();
    if (!ok)
      ctx_.fail(n, dotted(key), "unknown value '" + n.Scalar() + "' (valid: " + join(choices) + ")");
    out = n.Scalar();
  }
  void flag(const char* key, bool& out) {
    const YAML::Node n = get(key);
    if (!n) return;
    try {
      out = n.as<bool>();
    } catch (const YAML::Exception&) {
      ctx_.fail(n, dotted(key), "expected true or false, got " + scalar_text(n));
    }
  }
  YAML::Node get(const char* key) const {
    if (!node_.IsDefined() || node_.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node n = node_[key];
    if (!n.IsDefined() || n.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    if (ctx_.origins) (*ctx_.origins)[dotted(key)] = ctx_.where(n, dotted(key));
    return n;
  }
  std::string dotted(const char* key) const { return name_ + "." + key; }

 private:
  static bool parse(const YAML::Node& n, double& v) {
    if (!n.IsScalar()) return false;
    try {
      v = n.as<double>();
      return std::isfinite(v);
    } catch (const YAML::Exception&) {
      return false;
    }
  }
  std::string name_;
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
  const std::vector<std::string> sections{"mesh",    "material", "integrator",
                                          "contact", "protocol", "output"};
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.Scalar();
    bool ok = false;
    for (const auto& s : sections) ok = ok || s == key;
    if (!ok) ctx.fail(it->first, key, "unknown section (valid: " + join(sections) + ")");
  }

  Section mesh(root, "mesh", ctx, {"shape", "nodes", "size", "seed", "lloyd_iterations"});
  mesh.text("shape", p.mesh.shape, {"square", "disk"});
  // Upper bounds keep a typo from a run of days or an allocation that fails (1e6 nodes is 20x
  // the largest sheet studied; Lloyd converges in tens of iterations).
  mesh.integer("nodes", p.mesh.nodes, 10, 1e6);
  mesh.number("size", p.mesh.size, 0, kInf, true);
  mesh.integer("seed", p.mesh.seed, 0, 9007199254740992.0);
  mesh.integer("lloyd_iterations", p.mesh.lloyd_iterations, 0, 1000);

  Section mat(root, "material",ctx, {"thickness", "young_modulus", "density", "poisson", "ks", "kb",
                                     "mass", "mass_scale", "drag_ratio", "internal_damping_ratio"});
  auto& m = p.material;
  mat.number("thickness", m.thickness, 0, kInf, true);
  mat.number("young_modulus", m.young_modulus, 0, kInf, true);
  mat.number("density", m.density, 0, kInf, true);
  mat.number("poisson", m.poisson, 1.0 / 3.0 - 1e-12, 1.0 / 3.0 + 1e-12);
  mat.number("ks", m.ks, 0, kInf, true);
  mat.number("kb", m.kb, 0, kInf, true);
  mat.number("mass", m.mass, 0, kInf, true);
  const int direct = (m.ks > 0) + (m.kb > 0) + (m.mass > 0);
  if (direct != 0 && direct != 3) {
    const char* missing = m.ks > 0 ? (m.kb > 0 ? "mass" : "kb") : "ks";
    ctx.fail(root["material"], std::string("material.") + missing,
             "ks, kb and mass are given together or not at all");
  }
  mat.number("mass_scale", m.mass_scale, 0, kInf, true);
  mat.number("drag_ratio", m.drag_ratio, 0, kInf);
  mat.number("internal_damping_ratio", m.internal_damping_ratio, 0, kInf);

  Section in(root, "integrator", ctx,
             {"mode_initial", "bdf_order", "rtol", "atol", "h_init", "h_min", "h_max",
              "max_growth", "newton_tol", "newton_max_iters", "newton_target", "linear_solver",
              "block_size", "coarse_nodes", "cg_tol", "cg_tol_max", "cg_max_iters", "switch_up",
              "switch_down", "switch_window", "switch_min_steps", "explicit_rtol",
              "explicit_h_start", "plasticity", "plastic_c0", "plastic_gamma", "plastic_rate"});
  auto& s = p.integrator;
  std::string mode = s.mode_initial == IntegrationMode::Implicit ? "implicit" : "explicit";
  in.text("mode_initial", mode, {"implicit", "explicit"});
  s.mode_initial = parse_integration_mode(mode);
  in.integer("bdf_order", s.bdf_order, 1, 4);
  in.number("rtol", s.rtol, 0, kInf, true);
  in.number("atol", s.atol, 0, kInf, true);
  // Steps below 1e-12 s do not advance t (of order seconds) by more than its rounding, a hang.
  in.number("h_init", s.h_init, 1e-12, kInf);
  in.number("h_min", s.h_min, 1e-12, kInf);
  in.number("h_max", s.h_max, 0, kInf, true);
  in.number("max_growth", s.max_growth, 1, kInf, true);
  in.number("newton_tol", s.newton_tol, 0, kInf, true);
  in.integer("newton_max_iters", s.newton_max_iters, 1, 1000);
  in.integer("newton_target", s.newton_target, 1, 1000);
  std::string solver = to_string(s.linear_solver);
  in.text("linear_solver", solver, {"two_level", "block_jacobi", "cg", "incomplete_cholesky", "ldlt"});
  s.linear_solver = parse_linear_solver(solver);
  in.integer("block_size", s.block_size, 3, 600);  // dense blocks: memory ~ block_size x dofs
  in.integer("coarse_nodes", s.coarse_nodes, 3, 1e9);
  in.number("cg_tol", s.cg_tol, 0, 1, true, true);
  in.number("cg_tol_max", s.cg_tol_max, 0, 1, true, true);
  in.integer("cg_max_iters", s.cg_max_iters, 1, 1e9);
  in.number("switch_up", s.switch_up, 0, kInf, true);
  in.number("switch_down", s.switch_down, 0, kInf);
  in.integer("switch_window", s.switch_window, 1, 1e6);
  in.integer("switch_min_steps", s.switch_min_steps, 0, 1e9);
  in.number("explicit_rtol", s.explicit_rtol, 0, kInf, true);
  in.number("explicit_h_start", s.explicit_h_start, 0, kInf, true);
  in.flag("plasticity", s.plasticity);
  in.number("plastic_c0", s.plastic_c0, 0, 2, false, true);  // f divides by 2 - c0 (eq. 19)
  in.number("plastic_gamma", s.plastic_gamma, 0, kInf);
  in.number("plastic_rate", s.plastic_rate, 0, kInf, true);
  // Relations between keys: the error names a key of the pair that a --set override gave, else
  // the first of the pair that the file sets (its line), else the other (the defaults satisfy
  // every relation, so one of the two is always set when it fails).
  const auto relation = [&](bool ok, const char* a, const char* b, const std::string& what) {
    if (ok) return;
    const auto given = [&](const char* k) { return bool(in.get(k)); };
    const auto by_set = [&](const char* k) { return ctx.overrides.count(in.dotted(k)) > 0; };
    const char* key = by_set(a) ? a : by_set(b) ? b : given(a) ? a : given(b) ? b : a;
    const YAML::Node n = in.get(key);
    ctx.fail(n ? n : root, in.dotted(key), what);
  };
  const auto num = [](double v) {  // enough digits that two values in a message differ
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
  };
  relation(s.h_min <= s.h_max, "h_min", "h_max",
           "need integrator.h_min <= integrator.h_max, got " + num(s.h_min) + " > " + num(s.h_max));
  relation(s.h_min <= s.h_init, "h_init", "h_min",
           "need integrator.h_min <= integrator.h_init, got " + num(s.h_min) + " > " +
               num(s.h_init));
  relation(s.h_init <= s.h_max, "h_init", "h_max",
           "need integrator.h_init <= integrator.h_max, got " + num(s.h_init) + " > " +
               num(s.h_max));
  relation(s.cg_tol <= s.cg_tol_max, "cg_tol", "cg_tol_max",
           "need integrator.cg_tol <= integrator.cg_tol_max, got " + num(s.cg_tol) + " > " +
               num(s.cg_tol_max));
  relation(s.switch_down < s.switch_up, "switch_down", "switch_up",
           "need integrator.switch_down < integrator.switch_up, got " + num(s.switch_down) +
               " >= " + num(s.switch_up));

  Section ct(root, "contact", ctx, {"enabled", "sigma", "refinement", "stiffness", "skin",
                                          "fold_barrier"});
  ct.flag("enabled", p.contact.enabled);
  ct.number("sigma", p.contact.sigma, 0, kInf);
  ct.text("refinement", p.contact.refinement, {"auto", "0", "1", "2", "3"});
  ct.number("stiffness", p.contact.stiffness, 0, kInf);
  ct.number("skin", p.contact.skin, 0, 10);
  ct.flag("fold_barrier", p.contact.fold_barrier);

  Section pr(root, "protocol", ctx, {"cycles", "t_max", "stages"});
  pr.integer("cycles", p.protocol.cycles, 1, 1e6);
  pr.number("t_max", p.protocol.t_max, 0, kInf, true);
  const YAML::Node stages = pr.get("stages");
  if (stages) {
    if (!stages.IsSequence())
      ctx.fail(stages, "protocol.stages", "expected a list of stages, got " + scalar_text(stages));
    p.protocol.stages = stages;
  } else {
    p.protocol.stages = YAML::Node(YAML::NodeType::Sequence);
  }

  Section out(root, "output", ctx, {"dt", "checkpoint_wall_s", "crease_threshold", "xdmf"});
  out.number("dt", p.output.dt, 1e-6, kInf);  // every frame ends a chunk of steps
  out.number("checkpoint_wall_s", p.output.checkpoint_wall_s, 0, kInf);
  out.number("crease_threshold", p.output.crease_threshold, 0, 4, true);
  out.flag("xdmf", p.output.xdmf);
  return p;
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

std::string resolved_yaml(const Params& p) {
  YAML::Emitter e;
  e.SetDoublePrecision(17);
  e << YAML::BeginMap;
  e << YAML::Key << "mesh" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "shape" << YAML::Value << p.mesh.shape;
  e << YAML::Key << "nodes" << YAML::Value << p.mesh.nodes;
  e << YAML::Key << "size" << YAML::Value << p.mesh.size;
  e << YAML::Key << "seed" << YAML::Value << p.mesh.seed;
  e << YAML::Key << "lloyd_iterations" << YAML::Value << p.mesh.lloyd_iterations;
  e << YAML::EndMap;
  const auto& m = p.material;
  e << YAML::Key << "material" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "thickness" << YAML::Value << m.thickness;
  e << YAML::Key << "young_modulus" << YAML::Value << m.young_modulus;
  e << YAML::Key << "density" << YAML::Value << m.density;
  e << YAML::Key << "poisson" << YAML::Value << m.poisson;
  if (m.ks > 0) {
    e << YAML::Key << "ks" << YAML::Value << m.ks;
    e << YAML::Key << "kb" << YAML::Value << m.kb;
    e << YAML::Key << "mass" << YAML::Value << m.mass;
  }
  e << YAML::Key << "mass_scale" << YAML::Value << m.mass_scale;
  e << YAML::Key << "drag_ratio" << YAML::Value << m.drag_ratio;
  e << YAML::Key << "internal_damping_ratio" << YAML::Value << m.internal_damping_ratio;
  e << YAML::EndMap;
  const auto& s = p.integrator;
  e << YAML::Key << "integrator" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "mode_initial" << YAML::Value
    << (s.mode_initial == IntegrationMode::Implicit ? "implicit" : "explicit");
  e << YAML::Key << "bdf_order" << YAML::Value << s.bdf_order;
  e << YAML::Key << "rtol" << YAML::Value << s.rtol;
  e << YAML::Key << "atol" << YAML::Value << s.atol;
  e << YAML::Key << "h_init" << YAML::Value << s.h_init;
  e << YAML::Key << "h_min" << YAML::Value << s.h_min;
  e << YAML::Key << "h_max" << YAML::Value << s.h_max;
  e << YAML::Key << "max_growth" << YAML::Value << s.max_growth;
  e << YAML::Key << "newton_tol" << YAML::Value << s.newton_tol;
  e << YAML::Key << "newton_max_iters" << YAML::Value << s.newton_max_iters;
  e << YAML::Key << "newton_target" << YAML::Value << s.newton_target;
  e << YAML::Key << "linear_solver" << YAML::Value << to_string(s.linear_solver);
  e << YAML::Key << "block_size" << YAML::Value << s.block_size;
  e << YAML::Key << "coarse_nodes" << YAML::Value << s.coarse_nodes;
  e << YAML::Key << "cg_tol" << YAML::Value << s.cg_tol;
  e << YAML::Key << "cg_tol_max" << YAML::Value << s.cg_tol_max;
  e << YAML::Key << "cg_max_iters" << YAML::Value << s.cg_max_iters;
  e << YAML::Key << "switch_up" << YAML::Value << s.switch_up;
  e << YAML::Key << "switch_down" << YAML::Value << s.switch_down;
  e << YAML::Key << "switch_window" << YAML::Value << s.switch_window;
  e << YAML::Key << "switch_min_steps" << YAML::Value << s.switch_min_steps;
  e << YAML::Key << "explicit_rtol" << YAML::Value << s.explicit_rtol;
  e << YAML::Key << "explicit_h_start" << YAML::Value << s.explicit_h_start;
  e << YAML::Key << "plasticity" << YAML::Value << s.plasticity;
  e << YAML::Key << "plastic_c0" << YAML::Value << s.plastic_c0;
  e << YAML::Key << "plastic_gamma" << YAML::Value << s.plastic_gamma;
  e << YAML::Key << "plastic_rate" << YAML::Value << s.plastic_rate;
  e << YAML::EndMap;
  e << YAML::Key << "contact" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "enabled" << YAML::Value << p.contact.enabled;
  e << YAML::Key << "sigma" << YAML::Value << p.contact.sigma;
  e << YAML::Key << "refinement" << YAML::Value << p.contact.refinement;
  e << YAML::Key << "stiffness" << YAML::Value << p.contact.stiffness;
  e << YAML::Key << "skin" << YAML::Value << p.contact.skin;
  e << YAML::Key << "fold_barrier" << YAML::Value << p.contact.fold_barrier;
  e << YAML::EndMap;
  e << YAML::Key << "protocol" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "cycles" << YAML::Value << p.protocol.cycles;
  e << YAML::Key << "t_max" << YAML::Value << p.protocol.t_max;
  e << YAML::Key << "stages" << YAML::Value << p.protocol.stages;
  e << YAML::EndMap;
  e << YAML::Key << "output" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "dt" << YAML::Value << p.output.dt;
  e << YAML::Key << "checkpoint_wall_s" << YAML::Value << p.output.checkpoint_wall_s;
  e << YAML::Key << "crease_threshold" << YAML::Value << p.output.crease_threshold;
  e << YAML::Key << "xdmf" << YAML::Value << p.output.xdmf;
  e << YAML::EndMap;
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

}  // namespace crumple
