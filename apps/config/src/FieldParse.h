#pragma once
// Private to the config module: reads the keys of a parameter table
// (sensors/ParamField.h, FieldKinds.h) from a config section into a struct, with the
// range checks and located errors the config has always given. Custom entries
// go to a callback by name (their parsing is hand-written beside the visit).

#include <string>
#include <type_traits>

#include "ConfigNode.h"
#include "FieldKinds.h"
#include "QuantityText.h"
#include "ShortestNumber.h"
#include "Vec3Key.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

namespace detail {
inline void checkRange(const ConfigNode& n, const char* key, const sensors::Range& range,
                       double value) {
  if (!range.any() && n.has(key) && !range.contains(value)) {
    n.failKey(key, "must be " + rangeText(range) + " (got " + shortest(value) + ")");
  }
}

template <typename E>
std::string alternatives(const sensors::Choice<E>& choice) {
  std::string text;
  for (std::size_t i = 0; i < choice.names.size(); ++i) {
    if (i) text += i + 1 == choice.names.size() ? " or " : ", ";
    text += choice.names[i].name;
  }
  return text;
}

template <typename T, typename K>
void parseValue(const ConfigNode& n, const char* key, const K& kind, T& value) {
  if constexpr (kIsChecked<K>) {
    parseValue(n, key, kind.kind, value);  // the section checks the range
  } else if constexpr (std::is_same_v<K, sensors::Number>) {
    value = n.getDouble(key, value);
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, sensors::Duration>) {
    value = n.getDuration_s(key, value);
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, sensors::Length>) {
    value = n.getLength_m(key, value);
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, sensors::Rate>) {
    value = n.getFrequency_Hz(key, value);
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, sensors::Integer>) {
    const long long v = n.getInt(key, value);
    if (n.has(key) && (v < 1 || v > kind.max)) {
      n.failKey(key, "must be an integer in [1, " + std::to_string(kind.max) + "] (got " +
                         std::to_string(v) + ")");
    }
    value = static_cast<T>(v);
    if (kind.atLeast > 1 && v < kind.atLeast) {
      n.failKey(key, "must be >= " + std::to_string(kind.atLeast));
    }
  } else if constexpr (std::is_same_v<K, sensors::IntegerIn>) {
    const long long v = n.getInt(key, value);
    if (v < kind.min || v > kind.max) {
      n.failKey(key, "must be in [" + std::to_string(kind.min) + ", " + std::to_string(kind.max) +
                         "] (got " + std::to_string(v) + ")");
    }
    value = static_cast<T>(v);
  } else if constexpr (std::is_same_v<K, sensors::Flag>) {
    value = n.getBool(key, value);
  } else if constexpr (std::is_same_v<K, sensors::Text>) {
    value = n.getString(key, value);
  } else if constexpr (std::is_same_v<K, sensors::OptionalDuration>) {
    if (n.has(key)) value = n.getDuration_s(key, 0.0);
  } else if constexpr (std::is_same_v<K, Picoseconds>) {
    value = n.getDuration_s(key, value);
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, Bytes>) {
    // The upper bound keeps the conversion to an integer defined (found by fuzz_config).
    const double bytes = n.getBytes(key, static_cast<double>(value));
    if (!(bytes >= kind.min && bytes <= kind.max)) {
      n.failKey(key, "must be between " + bytesText(kind.min) + " and " + bytesText(kind.max));
    }
    value = static_cast<T>(bytes);
  } else if constexpr (std::is_same_v<K, Angle>) {
    value = static_cast<T>(n.getAngle_deg(key, value));
    checkRange(n, key, kind.range, value);
  } else if constexpr (std::is_same_v<K, Vec3>) {
    value = vec3Of(n, key, value);
  } else if constexpr (std::is_same_v<K, Rgb>) {
    if (n.has(key) && n.child(key).isScalar()) {
      value = T(static_cast<float>(n.getDouble(key, 1.0)));
    } else {
      value = vec3Of(n, key, value);
    }
    for (int c = 0; c < 3; ++c) {
      if (!(value[c] >= 0.0f)) n.failKey(key, "must be >= 0");
    }
  } else {  // Choice<E>
    const std::string name = n.getString(key, sensors::nameOf(kind, value));
    for (const auto& c : kind.names) {
      if (name == c.name) {
        value = c.value;
        return;
      }
    }
    n.failKey(key, "must be " + alternatives(kind) + " (got '" + name + "')");
  }
}
}  // namespace detail

/// Reads every Field (and In) of `table` into `s` (which holds the defaults);
/// calls custom(name) for each Custom entry, in table order.
template <typename Table, typename S, typename CustomFn>
void parseFields(const ConfigNode& n, const Table& table, S& s, CustomFn&& custom) {
  sensors::forEachField(table, [&](const auto& entry) {
    if constexpr (kHasValue<std::decay_t<decltype(entry)>>) {
      detail::parseValue(n, entry.name, entry.kind, valueIn(entry, s));
    } else {
      custom(entry.name);
    }
  });
}

template <typename Table, typename S>
void parseFields(const ConfigNode& n, const Table& table, S& s) {
  parseFields(n, table, s, [](const char*) {});
}

}  // namespace tofsim::config
