#pragma once
// Private to the pipeline: an NLOS capture's pictures for people to look at
// (issue 44: a camera render writes steady.png and depth.png; an NLOS one
// wrote none). H summed over time is the wall's steady image (H_steady.png,
// wall x to the right, wall y up); H summed over the wall's y (H_xt.png) and
// over its x (H_yt.png) are its projections over time, rows the optical
// path. An exhaustive scan's laser points are summed too. Colour-mapped PNGs
// with their colour bars (imaging/Pictures.h); the numbers stay in H.npy.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// The most rows a projection over time has: longer axes sum
/// nlosPictureBinsPerRow bins into a row (a picture, not the data).
inline constexpr std::size_t kNlosPictureRows = 2048;
std::size_t nlosPictureBinsPerRow(std::size_t bins);

/// The three projections of H (shape {T, ..., sx, sy}, time slowest), as
/// images: [0] steady (sy rows, top = the wall's +y; sx columns), [1] x-t
/// (a row per nlosPictureBinsPerRow bins, sx columns), [2] y-t (sy columns).
std::vector<Image> nlosProjections(const NlosVolume& volume);

/// Writes H_steady.png, H_xt.png and H_yt.png into `directory`; their names.
std::vector<std::string> writeNlosPictures(const std::filesystem::path& directory,
                                           const NlosVolume& volume);

}  // namespace tofsim::pipeline
