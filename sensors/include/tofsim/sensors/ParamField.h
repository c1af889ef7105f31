#pragma once
// The vocabulary of a parameter table (SensorFields.h): one entry per config
// key of a params struct, with its kind, range, unit and doc. Plain data, no
// YAML or JSON: the config module parses, emits and documents from the same
// entries (apps/config/src/Field*.h), the pipeline writes the sensor JSON
// (apps/pipeline/src/FieldJson.h). The default of a field is never written
// here: it is the struct's own initialiser, read from a default-constructed
// struct.

#include <limits>
#include <span>
#include <tuple>
#include <utility>

namespace tofsim::sensors {

/// Accepted values of a number: min..max, min exclusive or not. The config
/// error ("must be >= 0 (got -1)") and the doc column ("number >= 0") are
/// both written from it.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;
  constexpr bool any() const {
    return min == -std::numeric_limits<double>::infinity() &&
           max == std::numeric_limits<double>::infinity();
  }
  constexpr bool contains(double v) const {
    return (minExclusive ? v > min : v >= min) && v <= max;
  }
};
inline constexpr Range kAnyValue{};
inline constexpr Range kNonNegative{.min = 0.0};
inline constexpr Range kPositive{.min = 0.0, .minExclusive = true};
inline constexpr Range kFraction{.min = 0.0, .max = 1.0};

// Kinds: how a value is written in a config (the unit strings it accepts) and
// which C++ type holds it.
struct Number {  ///< double, a bare number
  Range range;
};
struct Duration {  ///< double seconds; "100 ps" or bare seconds
  Range range;
};
struct Length {  ///< double metres; "0.85 um" or bare metres
  Range range;
};
struct Rate {  ///< double 1/s; "2 MHz" or a bare number
  Range range;
};
/// An integer in [1, max]; then >= atLeast (its own error, as the config has always said).
struct Integer {
  long long max = 2147483647;
  long long atLeast = 1;
};
/// An integer in [min, max] ("must be in [min, max]"): the run config's form.
struct IntegerIn {
  long long min;
  long long max;
};
struct Flag {};              ///< bool
struct Text {};              ///< std::string
struct OptionalDuration {};  ///< std::optional<double> seconds; unset = from the render

template <typename E>
struct Name {
  const char* name;
  E value;
};
/// An enum written as one of its names.
template <typename E>
struct Choice {
  std::span<const Name<E>> names;
};

/// The config name of `value`.
template <typename E>
constexpr const char* nameOf(const Choice<E>& choice, E value) {
  for (const Name<E>& n : choice.names) {
    if (n.value == value) return n.name;
  }
  return choice.names.front().name;  // not reached for a declared enumerator
}

/// What is not the value: documentation and the sensor JSON's key.
struct Info {
  const char* unit = nullptr;  ///< doc unit of a bare number; nullptr: s, m or "-" by kind
  const char* json = nullptr;  ///< key in the sensor JSON metadata (name + SI unit suffix)
  const char* doc = "";        ///< one line
  /// 0 / unset means "from the render": this is the documented default, and the
  /// value is not emitted while unset (it is not an explicit value).
  const char* unset = nullptr;
  const char* note = nullptr;  ///< appended to the documented default: "0 (automatic)"
};

/// One config key of struct S, held in member `member` of type T.
template <typename S, typename T, typename K>
struct Field {
  const char* name;
  T S::*member;
  K kind;
  Info info;
};
template <typename S, typename T, typename K>
Field(const char*, T S::*, K, Info) -> Field<S, T, K>;

/// A key whose parse, emit and JSON are written by hand beside the generic
/// visit (lists, cross-field checks); the table holds its place in the key
/// order and its doc row. Visitors hand it to a callback by name.
struct Custom {
  const char* name;
  const char* type;
  const char* range;
  const char* defaultValue;
  const char* unit;
  const char* doc;
};

/// Calls f on every entry of a table (a std::tuple of Field and Custom), in order.
template <typename Table, typename F>
constexpr void forEachField(const Table& table, F&& f) {
  std::apply([&](const auto&... entry) { (f(entry), ...); }, table);
}

/// True for a Field (not a Custom entry).
template <typename E>
inline constexpr bool kIsField = false;
template <typename S, typename T, typename K>
inline constexpr bool kIsField<Field<S, T, K>> = true;

}  // namespace tofsim::sensors
