#pragma once
// Private to the CW-ToF model: how its outputs are made (an Array, or an
// Image with its ColorMappedImage), shared by the ideal and the device maps.

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"

namespace tofsim::sensors {

inline SensorOutput makeOutput(const std::string& name, SensorOutput::Kind kind,
                               std::vector<int64_t> shape, std::vector<std::string> axes,
                               std::vector<float> data, const std::string& unit,
                               const std::string& description) {
  SensorOutput o;
  o.name = name;
  o.kind = kind;
  o.shape = std::move(shape);
  o.axes = std::move(axes);
  o.data = std::move(data);
  o.unit = unit;
  o.description = description;
  return o;
}

/// What an image holds beyond its values: the frequency and depth range it
/// belongs to, and whether it is a signed error.
struct ImageMeaning {
  std::vector<std::pair<std::string, double>> attributes;
  bool signed_values = false;
};

inline void addImage(std::vector<SensorOutput>& outs, const std::string& name, int32_t H, int32_t W,
                     std::vector<float> data, const std::string& unit,
                     const std::string& description, const std::string& colormap,
                     const ImageMeaning& meaning = {}) {
  outs.push_back(makeOutput(name, SensorOutput::Kind::Image, {H, W}, {"y", "x"}, std::move(data),
                            unit, description));
  outs.back().attributes = meaning.attributes;
  outs.back().signed_values = meaning.signed_values;
  SensorOutput png = outs.back();
  png.kind = SensorOutput::Kind::ColorMappedImage;
  png.colormap = colormap;
  outs.push_back(std::move(png));
}

/// "cwtof_wiggling_error" (F, S), m (wigglingError_m), with its max |error|,
/// RMS and mean over all and per frequency as attributes.
SensorOutput wigglingErrorOutput(const std::vector<double>& wiggling_m,
                                 const std::vector<double>& frequencies_Hz);

inline std::string metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f m", m);
  return text;
}

}  // namespace tofsim::sensors
