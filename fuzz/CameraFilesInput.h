#pragma once
// How fuzz_camera_files turns its bytes into a config that reads them as one
// of a camera's files, shared with the regression test
// (tests/hardening/FuzzRegressionTest.cpp) so both load an input alike. The
// first byte picks the file, by its value mod 8: 0, an OpenCV calibration
// YAML (`camera.lens.calibration`, apps/config/src/LensConfig.cpp); 1, a
// CW-ToF correlation waveform as a CSV (`correlation: {file: ...}`,
// CwTofWaveformFile.cpp); 2, the same as a 1-D .npy; 3, a vignetting map
// .npy (`camera.vignetting`) of a 4 x 4 image; 4, a PSF kernel .npy
// (`camera.psf: {file: ...}`, PsfConfig.cpp); 5, a CW-ToF per-pixel delay
// map .npy (`delay_map`); 6, an ADC companding table CSV (`companding`,
// with a 12-bit ADC); 7, an empirical noise table CSV (`noise_table`, with
// `noise_model: table`). The rest is the file. A
// config that loads is run: every pixel's ray through the lens (for images
// of at most 4096 pixels) and the CW-ToF sensor on a lit volume, so a file
// the config accepts must be one the camera and sensor can use. `dir` holds
// a `scenes` link to configs/scenes.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "tofsim/capture/Camera.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/sensors/CwTof.h"

namespace tofsim::fuzz {

/// Writes the camera file and its config into `dir`; returns the config's
/// path, or an empty path for an empty input.
inline std::filesystem::path writeCameraFilesInput(const std::filesystem::path& dir,
                                                   const uint8_t* data, std::size_t size) {
  if (size == 0) return {};
  static constexpr const char* kFiles[] = {"calibration.yaml", "waveform.csv", "waveform.npy",
                                           "vignetting.npy",   "psf.npy",      "delay.npy",
                                           "companding.csv",   "noise.csv"};
  const int kind = data[0] % 8;
  const std::string file = kFiles[kind];
  std::ofstream(dir / file, std::ios::binary)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  const std::filesystem::path config = dir / "camera_files.yaml";
  std::ofstream yaml(config);
  yaml << "scene: scenes/cornell_box.gltf\n"
          "camera:\n"
          "  gltf_camera: cornell_camera\n";
  if (kind == 0) {
    yaml << "  lens: {calibration: " << file << "}\n";
  } else {
    yaml << "  resolution: [4, 4]\n";
  }
  if (kind == 3) yaml << "  vignetting: " << file << "\n";
  if (kind == 4) yaml << "  psf: {file: " << file << "}\n";
  yaml << "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
          "time: {start: 1.5 m, bin_width: 10 ps, bins: 8}\n"
          "sensors:\n"
          "  - type: cwtof\n"
          "    frequencies: [20 MHz, 50 MHz]\n";
  if (kind == 1 || kind == 2)
    yaml << "    waveform: measured\n    correlation: {file: " << file << "}\n";
  if (kind == 5) yaml << "    delay_map: " << file << "\n";
  if (kind == 6) yaml << "    adc_bits: 12\n    companding: " << file << "\n";
  if (kind == 7) yaml << "    noise_model: table\n    noise_table: " << file << "\n";
  return config;
}

/// Traces the loaded camera's pixel rays and runs its CW-ToF sensor on a lit
/// volume of its image and time axis.
inline void runCameraFiles(const config::RunConfig& run) {
  const capture::Camera& camera = run.camera.camera;
  if (static_cast<int64_t>(camera.width) * camera.height > 4096) return;
  const capture::PixelRays rays(camera);
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      (void)rays.direction(x, y);
      (void)camera.rayStepsAt(x, y);
    }
  }
  const auto& cwtof = std::get<sensors::CwTofParams>(run.sensors.at(0).params);
  TransientVolume volume(camera.width, camera.height, run.render.time, {"r", "g", "b"});
  for (std::size_t i = 0; i < volume.size(); ++i) volume.data()[i] = 0.01f * (i % 7);
  sensors::runCwTof(volume, cwtof, 1);
}

}  // namespace tofsim::fuzz
