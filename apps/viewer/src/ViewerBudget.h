#pragma once
// What the viewer's page may hold, in values of 2 bytes each (base64 makes
// each 2.67 characters of text). Together 8.25 Mi values = 16.5 MiB of data,
// 22 MiB of text: the page stays under kPageBytes whatever the render's size.

#include <cstddef>

namespace tofsim::viewer {

/// The volume (transient or NLOS H): pixels and bins, every channel.
inline constexpr std::size_t kVolumeValues = std::size_t{4} << 20;
/// The steady image (the volume summed over time), full resolution up to this.
inline constexpr std::size_t kImageValues = std::size_t{768} << 10;  // 512 x 512 x 3
/// One map (a sensor image, depth), and all maps together.
inline constexpr std::size_t kMapValues = std::size_t{256} << 10;  // 512 x 512
inline constexpr std::size_t kMapsValues = std::size_t{1536} << 10;
/// The sensors' histogram arrays (y, x, t) together (a SPAD's counts).
inline constexpr std::size_t kHistogramsValues = std::size_t{2} << 20;
/// At most this many maps and (y, x, t) arrays (their labels and notes
/// are the page's only text that grows with the folder).
inline constexpr std::size_t kMaxMaps = 256;
inline constexpr std::size_t kMaxHistograms = 16;
/// The page's size that follows from the budgets (base64: 4 characters per 3
/// bytes), plus the template and the metadata: checked after writing.
inline constexpr std::size_t kPageBytes = std::size_t{24} << 20;

}  // namespace tofsim::viewer
