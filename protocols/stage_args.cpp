// Stage parameter validation with file:line:column messages (stage_args.hpp).
#include "protocols/stage_args.hpp"

#include <cmath>
#include <sstream>

namespace crumple {

namespace {
std::string mark_text(const std::string& file, const YAML::Mark& m) {
  std::ostringstream os;
  os << file << ':' << (m.line + 1) << ':' << (m.column + 1);
  return os.str();
}
std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}
bool parse_number(const YAML::Node& n, double& out) {
  if (!n.IsScalar()) return false;
  try {
    out = n.as<double>();
    return std::isfinite(out);
  } catch (const YAML::Exception&) {
    return false;
  }
}
}  // namespace

StageArgs::StageArgs(const YAML::Node& node, std::string file, std::string path,
                     const std::vector<ParamSpec>& specs, const StageSets* sets)
    : node_(node), file_(std::move(file)), path_(std::move(path)), specs_(&specs), sets_(sets) {
  if (!node_.IsMap())
    throw InputError(mark_text(file_, node_.Mark()) + ": " + path_ + ": a stage must be a map");
  std::vector<std::string> valid;
  for (const auto& s : specs) valid.push_back(s.name);
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    if (key == "type") continue;
    bool known = false;
    for (const auto& s : specs) known = known || s.name == key;
    if (!known) {
      const std::string dotted = path_ + "." + key;
      const bool by_set = sets_ && sets_->count(dotted);
      throw InputError((by_set ? sets_->at(dotted) : mark_text(file_, it->first.Mark())) + ": " +
                       dotted + ": unknown parameter (valid: " + join(valid) + ")");
    }
  }
  // Validate every declared parameter now, so a bad value fails before anything runs.
  for (const auto& s : specs) {
    if (!given(s.name) && s.fallback.empty())
      throw InputError(mark_text(file_, node_.Mark()) + ": " + path_ + "." + s.name +
                       ": missing required parameter (" + s.help + ")");
    switch (s.kind) {
      case ParamSpec::Kind::Number: number(s.name); break;
      case ParamSpec::Kind::Text: text(s.name); break;
      case ParamSpec::Kind::Flag: flag(s.name); break;
      case ParamSpec::Kind::Numbers: numbers(s.name); break;
    }
  }
}

const ParamSpec& StageArgs::spec(const std::string& key) const {
  for (const auto& s : *specs_)
    if (s.name == key) return s;
  throw std::logic_error("stage parameter not declared: " + key);
}

bool StageArgs::given(const std::string& key) const { return node_[key].IsDefined(); }

std::string StageArgs::where(const std::string& key) const {
  const std::string dotted = path_ + "." + key;
  if (sets_)
    if (const auto it = sets_->find(dotted); it != sets_->end()) return it->second + ": " + dotted;
  const YAML::Node n = node_[key];
  return mark_text(file_, n.IsDefined() ? n.Mark() : node_.Mark()) + ": " + dotted;
}

void StageArgs::fail(const std::string& key, const std::string& what) const {
  throw InputError(where(key) + ": " + what);
}

void StageArgs::fail_both(const std::string& key, const std::string& other,
                          const std::string& what) const {
  // The key the file gives first is blamed; a defaulted one is named as the default.
  const std::string a = given(key) ? where(key) : path_ + "." + key + " (default)";
  const std::string b = given(other) ? where(other) : path_ + "." + other + " (default)";
  if (!given(key) && given(other)) throw InputError(b + ": " + what + " (the other key: " + a + ")");
  throw InputError(a + ": " + what + " (the other key: " + b + ")");
}

double StageArgs::number(const std::string& key) const {
  const ParamSpec& s = spec(key);
  double v;
  if (given(key)) {
    if (!parse_number(node_[key], v))
      fail(key, "expected a number, got '" + (node_[key].IsScalar() ? node_[key].Scalar()
                                                                     : std::string("a non-scalar")) +
                    "'");
  } else {
    v = std::stod(s.fallback);
  }
  check_range(s, key, v, -1);
  return v;
}

void StageArgs::check_range(const ParamSpec& s, const std::string& key, double v,
                            int index) const {
  const bool below = s.min_open ? !(v > s.min) : !(v >= s.min);
  if (below || v > s.max) {
    std::ostringstream os;
    if (index >= 0) os << "element " << index + 1 << " ";
    os << "must be " << (s.min_open ? "> " : ">= ") << s.min;
    if (std::isfinite(s.max)) os << " and <= " << s.max;
    os << ", got " << v;
    fail(key, os.str());
  }
}

std::vector<double> StageArgs::numbers(const std::string& key) const {
  const ParamSpec& s = spec(key);
  if (!given(key)) {
    const double v = std::stod(s.fallback);
    check_range(s, key, v, -1);
    return {v};
  }
  const YAML::Node n = node_[key];
  if (n.IsScalar()) return {number(key)};
  if (!n.IsSequence() || n.size() == 0)
    fail(key, "expected a number or a non-empty list of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    double v;
    if (!parse_number(n[i], v))
      fail(key, "element " + std::to_string(i + 1) + ": expected a number, got '" +
                    (n[i].IsScalar() ? n[i].Scalar() : std::string("a non-scalar")) + "'");
    check_range(s, key, v, static_cast<int>(i));
    out.push_back(v);
  }
  return out;
}

std::string StageArgs::text(const std::string& key) const {
  const ParamSpec& s = spec(key);
  std::string v = s.fallback;
  if (given(key)) {
    if (!node_[key].IsScalar()) fail(key, "expected a word");
    v = node_[key].Scalar();
  }
  if (!s.choices.empty()) {
    bool ok = false;
    for (const auto& c : s.choices) ok = ok || c == v;
    if (!ok) fail(key, "unknown value '" + v + "' (valid: " + join(s.choices) + ")");
  }
  return v;
}

bool StageArgs::flag(const std::string& key) const {
  const ParamSpec& s = spec(key);
  if (!given(key)) return s.fallback == "true";
  try {
    return node_[key].as<bool>();
  } catch (const YAML::Exception&) {
    fail(key, "expected true or false, got '" + node_[key].Scalar() + "'");
  }
}

}  // namespace crumple
