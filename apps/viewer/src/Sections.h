#pragma once
// The parts of the viewer's page, each read from one kind of output and
// added to the page's data (a JSON object; viewer.html draws it):
//   "volume": the time-resolved volume (a camera's transient, an NLOS H), its
//     time axis and downsampling; "image": its sum over time;
//   "maps": 2-D images with a colour bar (depth, every sensor map);
//   "histograms": sensor arrays (y, x, t) (a SPAD's counts), volumes as
//     "volume" is, each pixel's histogram plotted on a click;
//   "lidars": a lidar's range and intensity images (issue 43), maps as
//     makeMap makes them, drawn in their own section (addLidarVolume).
//   "notes": what was downsampled or left out, and why.

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace tofsim::viewer {

/// transient.json + transient.npy (or capture.h5): the volume and the steady
/// image. False, adding nothing, when the folder has no transient.json.
bool addCameraVolume(const std::filesystem::path& folder, nlohmann::json& page);

/// H.json + H.npy of an NLOS capture: H as a volume whose pixels are the
/// sensor points (an exhaustive scan's laser points summed). False when the
/// folder has no H.json.
bool addNlosVolume(const std::filesystem::path& folder, nlohmann::json& page);

/// lidar.json + waveforms.npy of a lidar: the waveforms as a volume whose
/// pixels are the beams (rings x azimuths), and its range and intensity
/// images (the first return's) in "lidars". False when the folder has no
/// lidar.json.
bool addLidarVolume(const std::filesystem::path& folder, nlohmann::json& page);

/// depth.npy and every sensor map under sensors/ (Images and y-x Arrays);
/// sensor arrays of axes (y, x, t) with a time axis (a SPAD's counts) as
/// "histograms": volumes of one channel, plotted beside the volume's on a click.
void addMaps(const std::filesystem::path& folder, nlohmann::json& page);

class VolumeReducer;
/// The "time" object of an output's metadata; InputError naming `file` unless
/// it has start_s, bin_width_s, start_m and bin_width_m as numbers.
const nlohmann::json& timeOf(const nlohmann::json& meta, const std::filesystem::path& file);
/// A reduced volume's entry: its values (float16) and its merged bins' axis.
nlohmann::json volumeEntry(const VolumeReducer& reducer, const nlohmann::json& time,
                           std::size_t bins, const std::vector<std::string>& channels);

/// One map for the page: `values` (height, width), averaged over blocks that
/// fit `budget` values, packed as uint16 between its finite extremes.
nlohmann::json makeMap(const std::string& group, const std::string& name, const std::string& unit,
                       const std::string& description, const std::vector<std::string>& axes,
                       std::size_t height, std::size_t width, const std::vector<float>& values,
                       std::size_t budget);

/// A JSON file of an output folder, parsed; InputError naming it otherwise.
nlohmann::json readJsonFile(const std::filesystem::path& path);
/// meta[key] when it is a string, else "" (a label: never an error).
std::string textOf(const nlohmann::json& meta, const char* key);
/// meta[key] when it is a list, each entry as text (a string, or its JSON).
std::vector<std::string> stringList(const nlohmann::json& meta, const char* key);

}  // namespace tofsim::viewer
