// Range messages, docs formatting and the struct check of the parameter schema (schema.hpp).
#include "sim/core/schema.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace crumple::schema {

std::string format_number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

namespace {

/// The bounds a check applies: the domain, narrowed by the input bounds for config values.
struct Bounds {
  double lo, hi;
  bool lo_open, hi_open;
};

Bounds bounds_of(const Key& k, bool input) {
  Bounds b{k.lo, k.hi, k.lo_open, k.hi_open};
  if (input && k.input_lo > b.lo) b.lo = k.input_lo, b.lo_open = false;
  if (input && k.input_hi < b.hi) b.hi = k.input_hi, b.hi_open = false;
  return b;
}

}  // namespace

std::string Key::range_error(double v, const std::string& text, bool input) const {
  const auto [lo, hi, lo_open, hi_open] = bounds_of(*this, input);
  std::ostringstream os;
  if (kind == Kind::Integer) {
    if (v >= lo && v <= hi) return {};
    if (std::isfinite(hi))
      os << "must be between " << static_cast<long long>(lo) << " and "
         << static_cast<long long>(hi) << ", got " << text;
    else
      os << "must be >= " << static_cast<long long>(lo) << ", got " << text;
    return os.str();
  }
  const bool low = lo_open ? !(v > lo) : !(v >= lo);
  const bool high = hi_open ? !(v < hi) : !(v <= hi);
  if (!low && !high) return {};
  os << "must be " << (lo_open ? "> " : ">= ") << lo;
  if (std::isfinite(hi)) os << (hi_open ? " and < " : " and <= ") << hi;
  os << ", got " << text;
  return os.str();
}

std::string Key::range_doc() const {
  if (!range_text.empty()) return range_text;
  if (kind != Kind::Real && kind != Kind::Integer) return {};
  const auto [lo, hi, lo_open, hi_open] = bounds_of(*this, true);
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  std::string a = format_number(lo), b = format_number(hi);
  if (kind == Kind::Integer) {
    // Whole numbers in full: "1000000", not "1e+06".
    if (has_lo) a = std::to_string(static_cast<long long>(lo));
    if (has_hi) b = std::to_string(static_cast<long long>(hi));
    if (has_lo && has_hi) return a + " to " + b;
    return has_lo ? ">= " + a : has_hi ? "<= " + b : "";
  }
  if (has_lo && has_hi)
    return std::string(lo_open ? "(" : "[") + a + ", " + b + (hi_open ? ")" : "]");
  if (has_lo) return (lo_open ? "> " : ">= ") + a;
  if (has_hi) return (hi_open ? "< " : "<= ") + b;
  return {};
}

const Key* Section::find(const std::string& key) const {
  for (const auto& k : keys)
    if (k.name == key) return &k;
  return nullptr;
}

std::vector<std::string> Section::names() const {
  std::vector<std::string> v;
  for (const auto& k : keys) v.push_back(k.name);
  return v;
}

std::string check(const Section& section, const void* values) {
  for (const auto& k : section.keys) {
    if (k.kind == Kind::Real || k.kind == Kind::Integer) {
      const double v = k.get_number(values);
      if (!std::isfinite(v)) return k.name + ": must be a finite number";
      if (k.kind == Kind::Integer && v != std::floor(v)) return k.name + ": must be a whole number";
      if (k.zero_is_unset && v == 0) continue;
      if (std::string e = k.range_error(v, format_number(v), false); !e.empty())
        return k.name + ": " + e;
    } else if (k.kind == Kind::Word) {
      const std::string w = k.get_word(values);
      bool ok = false;
      for (const auto& c : k.choices) ok = ok || c == w;
      if (!ok) return k.name + ": unknown value '" + w + "'";
    }
  }
  for (const auto& r : section.relations) {
    const double a = section.find(r.lhs)->get_number(values);
    const double b = section.find(r.rhs)->get_number(values);
    if (!r.holds(a, b))
      return r.lhs + ": need " + r.text() + ", got " + format_number(a) + (r.op == "<" ? " >= " : " > ") +
             format_number(b);
  }
  if (!section.all_or_none.empty()) {
    int given = 0;
    for (const auto& name : section.all_or_none) given += section.find(name)->get_number(values) != 0;
    if (given != 0 && given != static_cast<int>(section.all_or_none.size())) {
      std::string all;
      for (const auto& name : section.all_or_none) all += (all.empty() ? "" : ", ") + name;
      return all + ": given together or not at all";
    }
  }
  return {};
}

}  // namespace crumple::schema
