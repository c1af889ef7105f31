#pragma once
// Private to the config module: reads the keys of a parameter table
// (sensors/ParamField.h) from one `sensors:` entry into a struct, with the
// range checks and located errors the config has always given. Custom entries
// go to a callback by name (their parsing is hand-written beside the visit).

#include <string>
#include <type_traits>

#include "ConfigNode.h"
#include "QuantityText.h"
#include "ShortestNumber.h"
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
  if constexpr (std::is_same_v<K, sensors::Number>) {
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

/// Reads every Field of `table` into `s` (which holds the defaults); calls
/// custom(name) for each Custom entry, in table order.
template <typename Table, typename S, typename CustomFn>
void parseFields(const ConfigNode& n, const Table& table, S& s, CustomFn&& custom) {
  sensors::forEachField(table, [&](const auto& entry) {
    if constexpr (sensors::kIsField<std::decay_t<decltype(entry)>>) {
      detail::parseValue(n, entry.name, entry.kind, s.*entry.member);
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
