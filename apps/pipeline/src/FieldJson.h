#pragma once
// Private to the pipeline: the Fields of a parameter table
// (sensors/ParamField.h) as JSON values in SI units under their `json` key
// (dead_time_s, etendue_m2sr). Custom entries go to a callback by name, in
// table order.

#include <nlohmann/json.hpp>
#include <type_traits>

#include "tofsim/sensors/ParamField.h"

namespace tofsim::pipeline {

template <typename Table, typename S, typename CustomFn>
void fieldsJson(nlohmann::ordered_json& j, const Table& table, const S& s, CustomFn&& custom) {
  sensors::forEachField(table, [&](const auto& entry) {
    using E = std::decay_t<decltype(entry)>;
    if constexpr (sensors::kIsField<E>) {
      using K = std::decay_t<decltype(entry.kind)>;
      const auto& value = s.*entry.member;
      if constexpr (std::is_same_v<K, sensors::Number> || std::is_same_v<K, sensors::Duration> ||
                    std::is_same_v<K, sensors::Length> || std::is_same_v<K, sensors::Rate> ||
                    std::is_same_v<K, sensors::Integer> || std::is_same_v<K, sensors::IntegerIn> ||
                    std::is_same_v<K, sensors::Flag> || std::is_same_v<K, sensors::Text>) {
        j[entry.info.json] = value;
      } else if constexpr (std::is_same_v<K, sensors::OptionalDuration>) {
        static_assert(!sizeof(K), "an optional value has no JSON form: resolve it first");
      } else {  // Choice<E>
        j[entry.info.json] = sensors::nameOf(entry.kind, value);
      }
    } else {
      custom(entry.name);
    }
  });
}

template <typename Table, typename S>
void fieldsJson(nlohmann::ordered_json& j, const Table& table, const S& s) {
  fieldsJson(j, table, s, [](const char*) {});
}

}  // namespace tofsim::pipeline
