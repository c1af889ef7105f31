#pragma once
// Private to the config module: writes the Fields of a parameter table
// (sensors/ParamField.h) back as YAML, in the keys and units FieldParse.h
// reads. Custom entries go to a callback by name, in table order.

#include <yaml-cpp/yaml.h>

#include <string>
#include <type_traits>

#include "FieldKinds.h"
#include "QuantityText.h"
#include "ShortestNumber.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

namespace detail {
template <typename T, typename K>
void emitValue(YAML::Node& n, const char* key, const K& kind, const sensors::Info& info,
               const T& value) {
  if constexpr (kIsChecked<K>) {
    emitValue(n, key, kind.kind, info, value);
  } else if constexpr (std::is_same_v<K, sensors::OptionalDuration>) {
    if (value) n[key] = timeText(*value, durationText(*value));
  } else if constexpr (std::is_same_v<K, sensors::Text>) {
    // Empty text that means "not given" (info.unset) is not an explicit value.
    if (info.unset && value.empty()) return;
    n[key] = std::string(value);  // a std::filesystem::path too
  } else if constexpr (std::is_same_v<K, Picoseconds>) {
    n[key] = timeText(value, withUnit(value, 1e-12, "ps", "s"));
  } else if constexpr (std::is_same_v<K, Bytes>) {
    n[key] = std::to_string(value) + " B";
  } else if constexpr (std::is_same_v<K, Angle>) {
    n[key] = shortest(value) + " deg";
  } else if constexpr (std::is_same_v<K, Vec3> || std::is_same_v<K, Rgb>) {
    YAML::Node v(YAML::NodeType::Sequence);
    for (int i = 0; i < 3; ++i) v.push_back(shortest(value[i]));
    v.SetStyle(YAML::EmitterStyle::Flow);
    n[key] = v;
  } else if constexpr (std::is_same_v<K, sensors::Flag> || std::is_same_v<K, sensors::IntegerIn>) {
    n[key] = value;
  } else if constexpr (std::is_same_v<K, sensors::Number> || std::is_same_v<K, sensors::Rate> ||
                       std::is_same_v<K, sensors::Duration> || std::is_same_v<K, sensors::Length> ||
                       std::is_same_v<K, sensors::Integer>) {
    // 0 of a field "from the render" is not an explicit value: leave it out.
    if (info.unset && !(value > 0)) return;
    if constexpr (std::is_same_v<K, sensors::Duration>) {
      n[key] = timeText(value, durationText(value));
    } else if constexpr (std::is_same_v<K, sensors::Length>) {
      n[key] = shortest(value) + " m";
    } else if constexpr (std::is_same_v<K, sensors::Integer>) {
      n[key] = value;
    } else {
      n[key] = shortest(value);  // Rate too: a bare number is 1/s
    }
  } else {  // Choice<E>
    n[key] = sensors::nameOf(kind, value);
  }
}
}  // namespace detail

template <typename Table, typename S, typename CustomFn>
void emitFields(YAML::Node& n, const Table& table, const S& s, CustomFn&& custom) {
  sensors::forEachField(table, [&](const auto& entry) {
    if constexpr (kHasValue<std::decay_t<decltype(entry)>>) {
      detail::emitValue(n, entry.name, entry.kind, entry.info, valueIn(entry, s));
    } else {
      custom(entry.name);
    }
  });
}

template <typename Table, typename S>
void emitFields(YAML::Node& n, const Table& table, const S& s) {
  emitFields(n, table, s, [](const char*) {});
}

}  // namespace tofsim::config
