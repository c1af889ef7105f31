// Compile-time checks of the parameter tables (SensorFields.h); this file also
// builds the tables with the sensors target's own dependencies (no YAML, no
// JSON library), as they must.
#include "tofsim/sensors/SensorFields.h"

#include <string_view>

namespace tofsim::sensors {
namespace {

template <typename Entry>
constexpr std::string_view entryName(const Entry& e) {
  return e.name;
}

/// No config key twice in one table.
template <typename Table>
constexpr bool uniqueNames(const Table& table) {
  return std::apply(
      [](const auto&... e) {
        const std::string_view names[] = {entryName(e)...};
        for (std::size_t i = 0; i < sizeof...(e); ++i) {
          for (std::size_t j = i + 1; j < sizeof...(e); ++j) {
            if (names[i] == names[j]) return false;
          }
        }
        return true;
      },
      table);
}

/// Every Field of a table the sensor JSON visits has its JSON key.
template <typename Table>
constexpr bool jsonNamed(const Table& table) {
  bool ok = true;
  forEachField(table, [&](const auto& e) {
    if constexpr (kIsField<std::decay_t<decltype(e)>>) ok = ok && e.info.json != nullptr;
  });
  return ok;
}

static_assert(uniqueNames(kRadiometryFields) && uniqueNames(kBinsFields) &&
              uniqueNames(kStreakFields) && uniqueNames(kSpadFields) && uniqueNames(kCwTofFields));
static_assert(jsonNamed(kRadiometryFields) && jsonNamed(kStreakFields) && jsonNamed(kSpadFields) &&
              jsonNamed(kCwTofFields));

}  // namespace
}  // namespace tofsim::sensors
