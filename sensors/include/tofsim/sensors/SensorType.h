#pragma once
// One descriptor per sensor model: SensorType<Params> says everything the
// rest of tofsim needs to know about a model, so nothing dispatches on the
// type by hand. A SensorParams alternative without a complete descriptor does
// not compile (SensorSpec.h checks every alternative against SensorModel);
// its config side (parse, emit, checks against the image) is checked the
// same way in apps/config (SensorConfigType.h), which alone may use yaml-cpp.

#include <concepts>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/sensors/Apd.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/SensorInputs.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/Streak.h"
#include "tofsim/sensors/TimeKernel.h"

namespace tofsim::sensors {

/// What of a model its window loss depends on: its channel selection, its
/// instrument bins and the image rows it records (all when empty).
struct InstrumentWindow {
  SensorCommon common;
  InstrumentBins bins;
  std::vector<int32_t> rows;
};

/// One blur kernel a model builds (TimeKernel.h): the config key that sets it,
/// where it reaches and the bins it is laid out on (`unit` names them: "s"
/// for time, "px" for a spatial blur), so that the config can refuse one
/// wider than kMaxKernelReachBins where it reads the key.
struct TimeKernelUse {
  const char* key = "";
  KernelSupport support;
  double bin_width = 0.0;
  const char* unit = "s";
};

/// Why the kernel cannot be laid out (it reaches more than
/// kMaxKernelReachBins bins from zero delay), in words with its numbers;
/// empty when it can.
std::string timeKernelProblem(const TimeKernelUse& kernel);

/// Specialised once per model, below; never defined for anything else.
template <typename Params>
struct SensorType;

/// What a descriptor must provide.
template <typename P>
concept SensorModel = requires(const P& p, const VolumeShape& shape, const StreamOptions& options,
                               const Image* depth, int32_t width, int32_t height,
                               const TimeAxis& axis) {
  /// The `type:` of the config and the name in logs.
  { SensorType<P>::name } -> std::convertible_to<const char*>;
  /// The model, to be fed the volume as it streams (SensorStream.h); throws
  /// InputError when the spec does not fit the volume's shape.
  { SensorType<P>::open(p, shape, options) } -> std::same_as<std::unique_ptr<SensorStream>>;
  /// What the person running it should know about a render of this shape
  /// (image and time axis) and ground-truth depth (nullptr when none; e.g. a
  /// scene deeper than a CW-ToF's unambiguous range, an image that is not its
  /// device preset's); empty when all is well.
  { SensorType<P>::warnings(p, shape, depth) } -> std::same_as<std::vector<std::string>>;
  /// Upper estimate of the bytes its files take for an image and render axis.
  { SensorType<P>::outputBytes(p, width, height, axis) } -> std::same_as<std::uintmax_t>;
  /// The instrument window light can fall outside of (WindowLoss.h), or
  /// none for a model that integrates every bin.
  { SensorType<P>::window(p) } -> std::same_as<std::optional<InstrumentWindow>>;
  /// The blur kernels it builds for a render axis (none for CW-ToF).
  { SensorType<P>::timeKernels(p, axis) } -> std::same_as<std::vector<TimeKernelUse>>;
};

template <>
struct SensorType<StreakParams> {
  static constexpr const char* name = "streak";
  static std::unique_ptr<SensorStream> open(const StreakParams& p, const VolumeShape& shape,
                                            const StreamOptions& options);
  static std::vector<std::string> warnings(const StreakParams& p, const VolumeShape& shape,
                                           const Image* groundTruthDepth_m);
  static std::uintmax_t outputBytes(const StreakParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  static std::optional<InstrumentWindow> window(const StreakParams& p);
  static std::vector<TimeKernelUse> timeKernels(const StreakParams& p, const TimeAxis& render);
};

template <>
struct SensorType<SpadParams> {
  static constexpr const char* name = "spad";
  static std::unique_ptr<SensorStream> open(const SpadParams& p, const VolumeShape& shape,
                                            const StreamOptions& options);
  static std::vector<std::string> warnings(const SpadParams& p, const VolumeShape& shape,
                                           const Image* groundTruthDepth_m);
  static std::uintmax_t outputBytes(const SpadParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  static std::optional<InstrumentWindow> window(const SpadParams& p);
  static std::vector<TimeKernelUse> timeKernels(const SpadParams& p, const TimeAxis& render);
};

template <>
struct SensorType<CwTofParams> {
  static constexpr const char* name = "cwtof";
  static std::unique_ptr<SensorStream> open(const CwTofParams& p, const VolumeShape& shape,
                                            const StreamOptions& options);
  static std::vector<std::string> warnings(const CwTofParams& p, const VolumeShape& shape,
                                           const Image* groundTruthDepth_m);
  static std::uintmax_t outputBytes(const CwTofParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  /// CW-ToF integrates every render bin: it has no window to lose light from.
  static std::optional<InstrumentWindow> window(const CwTofParams& p);
  static std::vector<TimeKernelUse> timeKernels(const CwTofParams& p, const TimeAxis& render);
};

template <>
struct SensorType<ApdParams> {
  static constexpr const char* name = "apd";
  static std::unique_ptr<SensorStream> open(const ApdParams& p, const VolumeShape& shape,
                                            const StreamOptions& options);
  static std::vector<std::string> warnings(const ApdParams& p, const VolumeShape& shape,
                                           const Image* groundTruthDepth_m);
  static std::uintmax_t outputBytes(const ApdParams& p, int32_t width, int32_t height,
                                    const TimeAxis& render);
  static std::optional<InstrumentWindow> window(const ApdParams& p);
  static std::vector<TimeKernelUse> timeKernels(const ApdParams& p, const TimeAxis& render);
};

}  // namespace tofsim::sensors
