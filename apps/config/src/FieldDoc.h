#pragma once
// Private to the config module: the doc rows (ConfigKeys.h) of a parameter
// table: type, range, unit and doc from the table, the default from a
// default-constructed struct, as a config would write it.

#include <deque>
#include <string>
#include <type_traits>
#include <vector>

#include "FieldKinds.h"
#include "QuantityText.h"
#include "ShortestNumber.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

/// Owns the text of generated rows (ConfigKey holds const char*). A deque:
/// its strings never move as rows are added, so the pointers stay valid.
struct DocRows {
  std::deque<std::string> text;
  std::vector<ConfigKey> keys;
  const char* keep(std::string s) { return text.emplace_back(std::move(s)).c_str(); }
};

namespace detail {
/// An integer bound as the docs write it: 2^k for a power of two from 2^20 on.
inline std::string boundText(long long v) {
  if (v >= (1LL << 20) && (v & (v - 1)) == 0) {
    int k = 0;
    while ((1LL << k) < v) ++k;
    return "2^" + std::to_string(k);
  }
  return std::to_string(v);
}

struct KindDoc {
  const char* type;
  std::string range;
  const char* unit;
};

template <typename K>
KindDoc kindDoc(const K& kind) {
  if constexpr (kIsChecked<K>) {
    KindDoc doc = kindDoc(kind.kind);
    doc.range = kind.rangeDoc;
    return doc;
  } else if constexpr (std::is_same_v<K, sensors::Number>) {
    return {"number", rangeText(kind.range), "-"};
  } else if constexpr (std::is_same_v<K, sensors::Duration>) {
    return {"duration", rangeText(kind.range), "s"};
  } else if constexpr (std::is_same_v<K, sensors::Length>) {
    return {"length", rangeText(kind.range), "m"};
  } else if constexpr (std::is_same_v<K, sensors::Rate>) {
    return {"rate", rangeText(kind.range), "1/s"};
  } else if constexpr (std::is_same_v<K, sensors::Integer>) {
    return {"int", ">= " + std::to_string(kind.atLeast), "-"};
  } else if constexpr (std::is_same_v<K, sensors::IntegerIn>) {
    return {"int", "in [" + boundText(kind.min) + ", " + boundText(kind.max) + "]", "-"};
  } else if constexpr (std::is_same_v<K, sensors::Flag>) {
    return {"bool", "", "-"};
  } else if constexpr (std::is_same_v<K, sensors::OptionalDuration>) {
    return {"duration", "", "s"};
  } else if constexpr (std::is_same_v<K, Picoseconds>) {
    return {"duration", rangeText(kind.range), "s"};
  } else if constexpr (std::is_same_v<K, Bytes>) {
    return {"bytes", "in [" + bytesText(kind.min) + ", " + bytesText(kind.max) + "]", "B"};
  } else if constexpr (std::is_same_v<K, Angle>) {
    return {"angle", kind.rangeDoc ? kind.rangeDoc : rangeText(kind.range), "deg"};
  } else if constexpr (std::is_same_v<K, Vec3>) {
    return {"vec3", "", "-"};
  } else if constexpr (std::is_same_v<K, Rgb>) {
    return {"number or vec3", ">= 0", "-"};
  } else {  // Text, Choice<E>
    return {"string", "", "-"};
  }
}

/// The default as written in a config: "0", "0.3", "10 ps", "true", "turbo".
template <typename T, typename K>
std::string defaultText(const K& kind, const T& value) {
  if constexpr (kIsChecked<K>) {
    return defaultText(kind.kind, value);
  } else if constexpr (std::is_same_v<K, sensors::Flag>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_same_v<K, sensors::Text>) {
    return value;
  } else if constexpr (std::is_same_v<K, sensors::Integer> ||
                       std::is_same_v<K, sensors::IntegerIn>) {
    return std::to_string(value);
  } else if constexpr (std::is_same_v<K, sensors::OptionalDuration>) {
    return value ? durationText(*value) : "unset";
  } else if constexpr (std::is_same_v<K, Picoseconds>) {
    return value == 0.0 ? "0" : durationText(value);
  } else if constexpr (std::is_same_v<K, Bytes>) {
    return bytesText(static_cast<double>(value));
  } else if constexpr (std::is_same_v<K, Angle>) {
    return shortest(value);
  } else if constexpr (std::is_same_v<K, Vec3> || std::is_same_v<K, Rgb>) {
    if (std::is_same_v<K, Rgb> && value[0] == value[1] && value[1] == value[2]) {
      return shortest(value[0]);
    }
    return "[" + shortest(value[0]) + ", " + shortest(value[1]) + ", " + shortest(value[2]) + "]";
  } else if constexpr (std::is_same_v<K, sensors::Number> || std::is_same_v<K, sensors::Rate> ||
                       std::is_same_v<K, sensors::Duration> || std::is_same_v<K, sensors::Length>) {
    if (value == 0.0) return "0";
    if constexpr (std::is_same_v<K, sensors::Duration>) return durationText(value);
    if constexpr (std::is_same_v<K, sensors::Length>) return shortest(value) + " m";
    return shortest(value);
  } else {  // Choice<E>
    return sensors::nameOf(kind, value);
  }
}
}  // namespace detail

/// Appends one row per entry of `table`, keyed "<prefix>.<name>", the
/// defaults read from `defaults`.
template <typename S, typename Table>
void addDocRows(DocRows& rows, const char* prefix, const Table& table, const S& defaults) {
  sensors::forEachField(table, [&](const auto& e) {
    const std::string path = std::string(prefix) + "." + e.name;
    if constexpr (kHasValue<std::decay_t<decltype(e)>>) {
      const detail::KindDoc kind = detail::kindDoc(e.kind);
      std::string value = e.info.unset ? std::string(e.info.unset)
                                       : detail::defaultText(e.kind, valueIn(e, defaults));
      if (e.info.note) value += std::string(" (") + e.info.note + ")";
      rows.keys.push_back({rows.keep(path), kind.type, rows.keep(kind.range),
                           rows.keep(std::move(value)), e.info.unit ? e.info.unit : kind.unit,
                           e.info.doc});
    } else {
      rows.keys.push_back({rows.keep(path), e.type, e.range, e.defaultValue, e.unit, e.doc});
    }
  });
}

/// As above, the defaults a default-constructed S holds.
template <typename S, typename Table>
void addDocRows(DocRows& rows, const char* prefix, const Table& table) {
  addDocRows(rows, prefix, table, S{});
}

}  // namespace tofsim::config
