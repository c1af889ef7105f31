#pragma once
// Private to the config module: the `output:` section's parameter table (see RunFields.h).

#include <array>
#include <tuple>

#include "RunFields.h"

namespace tofsim::config {

// clang-format off
inline constexpr std::array<Name<OutputFormat>, 2> kOutputFormatNames{
    {{"npy", OutputFormat::Npy}, {"hdf5", OutputFormat::Hdf5}}};
inline constexpr std::array<Name<VideoToneMap>, 2> kToneMapNames{
    {{"global", VideoToneMap::Global}, {"log", VideoToneMap::Log}}};

// The keys of `output`; `components` and `plot_ranges` are lists parsed and
// written beside the visit (RunSections.cpp, EffectiveConfig.cpp).
inline constexpr auto kOutputFields = std::tuple{
    Field{"directory", &OutputConfig::directory, Text{},
          {.doc = "output folder (`-o` overrides), relative to the folder the command runs in (unlike `scene` and the other files a config names, which are relative to the config's folder)"}},
    Field{"format", &OutputConfig::format, Choice<OutputFormat>{kOutputFormatNames},
          {.doc = "`npy`: each array its own `.npy` (`transient.npy`, `direct.npy`, ...); `hdf5`: the volumes, `depth`, `steady` and every sensor array as datasets of one `capture.h5`, chunked along the pixels, shuffle + gzip, each with its metadata as attributes (README.md, \"What a render writes\"); the EXR and PNG pictures and the JSON files stay. An `nlos` capture writes its own files either way"}},
    Field{"transient", &OutputConfig::transient, Flag{},
          {.doc = "`transient.npy` (H, W, T, 3) + `transient.json` (axes, units, time axis)"}},
    Field{"steady", &OutputConfig::steady, Flag{},
          {.doc = "`steady.exr` + `steady.png` (sum over time)"}},
    Field{"depth", &OutputConfig::depth, Flag{},
          {.doc = "`depth.exr` (channels Y and Z, the same metres; 0 = no surface), `depth.npy` (float32 (H, W), metres) + `depth.png`"}},
    Field{"frames", &OutputConfig::frames, Flag{},
          {.doc = "`frames/frame_NNNNN.exr`, one per time bin"}},
    Field{"video", &OutputConfig::video, Flag{},
          {.doc = "`transient.mp4`: light in flight, one frame per `video_stride` bins, time stamp in each frame"}},
    Field{"frame_pngs", &OutputConfig::frame_pngs, Flag{},
          {.doc = "`frames/frame_NNNNN.png` (NNNNN = time bin): the video's frames as PNG (needs no `video`)"}},
    Field{"video_tone_map", &OutputConfig::video_tone_map, Choice<VideoToneMap>{kToneMapNames},
          {.doc = "`global`: linear, one scale for the whole video (the 99.5th percentile of all frames' values maps to white); `log`: `1 + log10(v / white) / 4`, four decades below that white"}},
    Field{"video_stride", &OutputConfig::video_stride, IntegerIn{1, 1 << 20},
          {.unit = "bins", .doc = "one frame every `video_stride` time bins"}},
    Field{"video_window", &OutputConfig::video_window, IntegerIn{1, 1 << 20},
          {.unit = "bins", .doc = "exposure of each video frame / frame PNG: frame t sums bins t-(w-1)/2 .. t+w/2, so a wavefront shows w bins wide"}},
    Field{"video_fps", &OutputConfig::video_fps, Number{kPositive},
          {.unit = "1/s", .doc = "frames per second of the video"}},
    Field{"max_bytes", &OutputConfig::max_bytes, Bytes{1.0, 0x1p60},
          {.doc = "before rendering, the outputs' size is estimated (`.npy` volumes, EXR frames and sensor arrays exactly, PNG and MP4 roughly); a run over this, or over the output folder's free space, fails at once naming the sizes and the keys that drive them"}},
    Custom{"components", "list", "", "[]", "-", "also write `direct` (`direct.npy`), `indirect` (`indirect.npy`) and/or `bounce1` .. `bounceN` (`bounce<k>.npy`, the light of exactly k indirect bounces, k <= `render.indirect.bounces`, `renderer: ir` only; `indirect` = their sum exactly)"},
    Custom{"plot_ranges", "map of [lo, hi]", "lo < hi", "{}", "unit of the picture", "fixed colour ranges, so pictures compare across runs: key = the PNG's path without `.png` (`depth`, `steady`, `sensors/<sensor>/<output>`), e.g. `{depth: [0.5, 3], sensors/cwtof/cwtof_mpi_error: [-0.05, 0.05]}`; `steady` maps lo..hi to black..white; a key that names no picture of the run is warned about; a sensor picture's JSON records the range it was drawn with, fixed or automatic (`picture.range`, `sensors/README.md`)"},
};
// clang-format on

}  // namespace tofsim::config
