#pragma once
// The file names of a camera render, written once (OutputProducts.h lists
// which a run writes). A header of its own, without the config's schema, so
// readers of a saved render (SavedVolume.cpp, also built alone into a fuzz
// target) need nothing but the names.

#include <cstdint>
#include <string>
#include <string_view>

namespace tofsim::pipeline {

/// File names of a camera render, relative to its output folder.
namespace files {
inline constexpr std::string_view kTransient = "transient.npy";  ///< direct + indirect
inline constexpr std::string_view kDirect = "direct.npy";
inline constexpr std::string_view kIndirect = "indirect.npy";
inline constexpr std::string_view kMetadata = "transient.json";
inline constexpr std::string_view kSteadyExr = "steady.exr";
inline constexpr std::string_view kSteadyPng = "steady.png";
inline constexpr std::string_view kDepthExr = "depth.exr";
inline constexpr std::string_view kDepthNpy = "depth.npy";
inline constexpr std::string_view kDepthPng = "depth.png";
inline constexpr std::string_view kVideo = "transient.mp4";
/// output.format: hdf5: the volumes, steady, depth and the sensors' arrays.
inline constexpr std::string_view kCapture = "capture.h5";
/// bounce<k>.npy: the light of exactly k indirect bounces.
std::string bounce(int32_t k);
/// frames/frame_NNNNN.exr and .png: time bin `bin` of the volume.
std::string frameExr(int32_t bin);
std::string framePng(int32_t bin);
}  // namespace files

}  // namespace tofsim::pipeline
