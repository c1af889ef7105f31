#pragma once
// One descriptor per sensor model: SensorType<Params> says everything the
// rest of tofsim needs to know about a model, so nothing dispatches on the
// type by hand. A SensorParams alternative without a complete descriptor does
// not compile (SensorSpec.h checks every alternative against SensorModel);
// its config side (parse, emit, checks against the image) is checked the
// same way in core/config (SensorConfigType.h), which alone may use yaml-cpp.

#include <concepts>
#include <cstdint>
#include <string>
#include <vector>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/SensorInputs.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/Streak.h"

namespace tofsim::sensors {

/// Specialised once per model, below; never defined for anything else.
template <typename Params>
struct SensorType;

/// What a descriptor must provide.
template <typename P>
concept SensorModel = requires(const P& p, const SensorInputs& in, const TransientVolume& v,
                               int32_t width, int32_t height, const TimeAxis& axis) {
  /// The `type:` of the config and the name in logs.
  { SensorType<P>::name } -> std::convertible_to<const char*>;
  /// Runs the model (throws InputError when the spec does not fit the inputs).
  { SensorType<P>::run(p, in) } -> std::same_as<std::vector<SensorOutput>>;
  /// What the person running it should know about these inputs (e.g. a scene
  /// deeper than a CW-ToF's unambiguous range); empty when all is well.
  { SensorType<P>::warnings(p, in) } -> std::same_as<std::vector<std::string>>;
  /// Upper estimate of the bytes its files take for an image and render axis.
  { SensorType<P>::outputBytes(p, width, height, axis) } -> std::same_as<std::uintmax_t>;
  /// Fraction of the light it is given that its instrument window drops.
  { SensorType<P>::windowLossFraction(p, v) } -> std::same_as<double>;
};

template <>
struct SensorType<StreakParams> {
  static constexpr const char* name = "streak";
  static std::vector<SensorOutput> run(const StreakParams& p, const SensorInputs& in);
  static std::vector<std::string> warnings(const StreakParams& p, const SensorInputs& in);
  static std::uintmax_t outputBytes(const StreakParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  static double windowLossFraction(const StreakParams& p, const TransientVolume& volume);
};

template <>
struct SensorType<SpadParams> {
  static constexpr const char* name = "spad";
  static std::vector<SensorOutput> run(const SpadParams& p, const SensorInputs& in);
  static std::vector<std::string> warnings(const SpadParams& p, const SensorInputs& in);
  static std::uintmax_t outputBytes(const SpadParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  static double windowLossFraction(const SpadParams& p, const TransientVolume& volume);
};

template <>
struct SensorType<CwTofParams> {
  static constexpr const char* name = "cwtof";
  static std::vector<SensorOutput> run(const CwTofParams& p, const SensorInputs& in);
  static std::vector<std::string> warnings(const CwTofParams& p, const SensorInputs& in);
  static std::uintmax_t outputBytes(const CwTofParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  /// CW-ToF integrates every render bin: it has no window to lose light from.
  static double windowLossFraction(const CwTofParams& p, const TransientVolume& volume);
};

}  // namespace tofsim::sensors
