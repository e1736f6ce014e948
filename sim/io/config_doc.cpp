// Listing and markdown tables of the configuration keys (config_doc.hpp).
#include "sim/io/config_doc.hpp"

#include "sim/io/config_schema.hpp"

#include <algorithm>
#include <sstream>

namespace crumple {

namespace {

using schema::Key;
using schema::Kind;

std::string type_of(const Key& k) {
  switch (k.kind) {
    case Kind::Real: return "number";
    case Kind::Integer: return "integer";
    case Kind::Word: return "word";
    case Kind::Flag: return "bool";
    case Kind::List: return "list";
  }
  return "?";
}

std::string default_of(const Key& k, const void* defaults) {
  return k.default_text.empty() ? value_text(k, defaults) : k.default_text;
}

std::string range_of(const Key& k) {
  if (k.kind == Kind::Word) {
    std::string s;
    for (const auto& c : k.choices) s += (s.empty() ? "" : ", ") + c;
    return s;
  }
  return k.range_doc();
}

/// The relations and groups of a section as one line each.
std::vector<std::string> rules_of(const schema::Section& s) {
  std::vector<std::string> v;
  for (const auto& r : s.relations) v.push_back(r.text());
  if (!s.all_or_none.empty()) {
    std::string g;
    for (const auto& k : s.all_or_none) g += (g.empty() ? "" : ", ") + k;
    v.push_back(g + ": all or none");
  }
  return v;
}

}  // namespace

std::string config_keys_text() {
  const Params defaults;
  std::ostringstream os;
  for (const auto& cs : config_schema()) {
    const auto& s = *cs.section;
    os << s.name << ": " << s.meaning << "\n";
    std::size_t width = 0;
    for (const auto& k : s.keys) width = std::max(width, s.name.size() + 1 + k.name.size());
    for (const auto& k : s.keys) {
      std::string key = s.name + "." + k.name;
      key.resize(width, ' ');
      os << "  " << key << "  " << type_of(k) << ", default " << default_of(k, cs.of_const(defaults));
      if (const std::string r = range_of(k); !r.empty())
        os << (k.kind == Kind::Word ? ", one of " : ", ") << r;
      if (k.unit != "-" && k.kind == Kind::Real) os << ", " << k.unit;
      if (k.resumable) os << ", may change on --resume";
      os << "\n    " << k.meaning << "\n";
    }
    for (const auto& r : rules_of(s)) os << "  need " << r << "\n";
  }
  return os.str();
}

std::string config_keys_markdown() {
  const Params defaults;
  std::ostringstream os;
  for (const auto& cs : config_schema()) {
    const auto& s = *cs.section;
    os << "<!-- keys: " << s.name << " -->\n";
    os << "| key | type | unit | default | range | meaning |\n|---|---|---|---|---|---|\n";
    for (const auto& k : s.keys) {
      std::string meaning = k.meaning;
      if (k.resumable) meaning += "; may change on `--resume`";
      // A '|' inside a cell would end it.
      std::string range = range_of(k);
      std::replace(range.begin(), range.end(), '|', '/');
      os << "| `" << k.name << "` | " << type_of(k) << " | " << (k.kind == Kind::Real ? k.unit : "-")
         << " | " << default_of(k, cs.of_const(defaults)) << " | " << range << " | " << meaning
         << " |\n";
    }
    const auto rules = rules_of(s);
    if (!rules.empty()) {
      os << "\nRelations:";
      for (std::size_t i = 0; i < rules.size(); ++i) os << (i ? "; " : " ") << "`" << rules[i] << "`";
      os << ".\n";
    }
    os << "<!-- /keys -->\n";
  }
  return os.str();
}

}  // namespace crumple
