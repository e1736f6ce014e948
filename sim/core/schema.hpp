// A declarative parameter schema: each key of a config section once, with its type, unit,
// range, allowed words, one-line meaning and the relations between keys, bound to the member of
// the plain struct that holds it. The default is the struct's own member initialiser (read
// from a default-constructed struct), so no default is written twice.
//
// The config reader, its validator, the resolved-config emitter, `--set`, `crumple-sim
// --list-keys` and the tables of docs/CONFIG.md are all driven by these tables
// (sim/io/config_schema.cpp composes the sections; sim/integrate/settings_schema.cpp owns the
// integrator's).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace crumple::schema {

enum class Kind { Real, Integer, Word, Flag, List };

/// One key. Access is type-erased over a pointer to the section's struct; the builders below
/// make the accessors from a member pointer, so they cannot point at the wrong type.
struct Key {
  std::string name;
  Kind kind = Kind::Real;
  std::string unit = "-";  ///< SI unit for the docs ("m", "s", "Pa"), "-" when dimensionless
  std::string meaning;     ///< one line
  /// The domain: what the method needs, checked for every value (config or code).
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  /// Tighter bounds for values a user types (a step that does not advance t, an allocation that
  /// fails, a run of days): the config reader enforces them, code (tests, benches) may go beyond.
  double input_lo = -std::numeric_limits<double>::infinity();
  double input_hi = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  ///< Word: the allowed values
  /// Real: 0 stands for "not given" (derived from other keys): a value the config gives must be
  /// in range, and the emitter leaves the key out while it is 0.
  bool zero_is_unset = false;
  std::string default_text;  ///< docs: replaces the printed default (e.g. "0: h_eff")
  std::string range_text;    ///< docs: replaces the printed range (e.g. "= 1/3")
  bool resumable = false;    ///< may change when a run is resumed (docs/CONFIG.md)

  std::function<double(const void*)> get_number;  ///< Real, Integer, Flag (0 or 1)
  std::function<void(void*, double)> set_number;
  std::function<std::string(const void*)> get_word;  ///< Word
  std::function<void(void*, const std::string&)> set_word;

  // Fluent setters for the tables.
  Key& at_least(double v) { lo = v, lo_open = false; return *this; }
  Key& above(double v) { lo = v, lo_open = true; return *this; }
  Key& at_most(double v) { hi = v, hi_open = false; return *this; }
  Key& below(double v) { hi = v, hi_open = true; return *this; }
  Key& in(double a, double b) { return at_least(a).at_most(b); }
  Key& units(std::string u) { unit = std::move(u); return *this; }
  Key& means(std::string m) { meaning = std::move(m); return *this; }
  Key& unset_when_zero() { zero_is_unset = true; return *this; }
  Key& shown_default(std::string t) { default_text = std::move(t); return *this; }
  Key& shown_range(std::string t) { range_text = std::move(t); return *this; }
  Key& may_change_on_resume() { resumable = true; return *this; }
  Key& input_at_least(double v) { input_lo = v; return *this; }
  Key& input_at_most(double v) { input_hi = v; return *this; }

  /// Empty when `v` is in range, else "must be ... , got TEXT" (TEXT as the user wrote it).
  /// `input`: the range of a value given in a config (domain and input bounds together).
  std::string range_error(double v, const std::string& text, bool input = true) const;
  /// The range of a config value as the docs print it ("> 0", "1 to 4", "[0, 2)"); empty when
  /// unbounded.
  std::string range_doc() const;
};

/// lhs OP rhs between two numeric keys of one section, OP "<=" or "<". When it fails the
/// message names `blame` if the user set it, else the other key.
struct Relation {
  std::string lhs, op, rhs;
  std::string blame;  ///< the key to name first; empty: lhs
  bool holds(double a, double b) const { return op == "<" ? a < b : a <= b; }
  std::string text() const { return lhs + " " + op + " " + rhs; }
};

struct Section {
  std::string name;
  std::string meaning;  ///< one line for --list-keys and the docs
  std::vector<Key> keys;
  std::vector<Relation> relations;
  /// Keys that are given together or not at all (zero_is_unset Reals).
  std::vector<std::string> all_or_none;

  const Key* find(const std::string& key) const;
  std::vector<std::string> names() const;
};

/// Formats a number for messages and docs: shortest of %g and enough digits to round-trip.
std::string format_number(double v);

// ---- builders from member pointers ----------------------------------------------------------

template <class T, class M>
Key real(const char* name, M T::*member) {
  Key k;
  k.name = name;
  k.kind = Kind::Real;
  k.get_number = [member](const void* s) { return static_cast<double>(static_cast<const T*>(s)->*member); };
  k.set_number = [member](void* s, double v) { static_cast<T*>(s)->*member = static_cast<M>(v); };
  return k;
}

template <class T, class M>
Key integer(const char* name, M T::*member) {
  Key k = real(name, member);
  k.kind = Kind::Integer;
  k.unit.assign(1, '-');  // not = "-": GCC 12 warns of a false overlap (-Wrestrict)
  return k;
}

template <class T>
Key flag(const char* name, bool T::*member) {
  Key k;
  k.name = name;
  k.kind = Kind::Flag;
  k.get_number = [member](const void* s) { return static_cast<const T*>(s)->*member ? 1.0 : 0.0; };
  k.set_number = [member](void* s, double v) { static_cast<T*>(s)->*member = v != 0; };
  return k;
}

/// A word held as a string member.
template <class T>
Key word(const char* name, std::string T::*member, std::vector<std::string> choices) {
  Key k;
  k.name = name;
  k.kind = Kind::Word;
  k.choices = std::move(choices);
  k.get_word = [member](const void* s) { return static_cast<const T*>(s)->*member; };
  k.set_word = [member](void* s, const std::string& v) { static_cast<T*>(s)->*member = v; };
  return k;
}

/// A word held as an enum member, with its two conversions.
template <class T, class E>
Key word(const char* name, E T::*member, std::vector<std::string> choices,
         std::string (*to_text)(E), E (*from_text)(const std::string&)) {
  Key k;
  k.name = name;
  k.kind = Kind::Word;
  k.choices = std::move(choices);
  k.get_word = [member, to_text](const void* s) { return to_text(static_cast<const T*>(s)->*member); };
  k.set_word = [member, from_text](void* s, const std::string& v) {
    static_cast<T*>(s)->*member = from_text(v);
  };
  return k;
}

/// A list held elsewhere (the stage list): the schema only documents it.
inline Key list(const char* name) {
  Key k;
  k.name = name;
  k.kind = Kind::List;
  return k;
}

/// Checks a filled struct against its section: ranges, relations and groups. Returns the first
/// problem as "KEY: what" (empty: all fine). For code that builds settings without a config
/// file (tests, benches): the config reader reports the same rules with file positions.
std::string check(const Section& section, const void* values);

}  // namespace crumple::schema
