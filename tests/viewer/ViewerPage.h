#pragma once
// The viewer tests' side of the page: the data `tofsim view` embedded in a
// page, its packed arrays decoded as the page's script decodes them
// (apps/viewer/src/PackedArray.h), and a render of the Cornell box small
// enough for a test.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"

namespace tofsim::test {

/// The Cornell box at 12 x 10 pixels (width x height: rows and columns
/// differ, so a transposed pixel shows), 96 bins of 50 ps (1.5 m .. 2.94 m of
/// path: the box's direct light and some indirect), CPU backend, its sensors.
inline CommandResult renderSmallCornell(const std::filesystem::path& out,
                                        const std::string& extra = "") {
  return runCli("render " + kCornellConfig + " -o " + out.string() +
                " --set camera.resolution=[12,10] --set time.bins=96 --set time.bin_width=\"50 ps\""
                " --set render.backend=cpu"
                " --set output.video=false --set sensors.0.plot_pixels=[[4,4]]"
                " --set sensors.1.rows=[4] -q " +
                extra);
}

/// Runs a shell command; its exit code and stdout (stderr as the command routes it).
inline CommandResult runShell(const std::string& command) {
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

/// The JSON between the page's data marker element's tags.
inline nlohmann::json pageData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"tofsim-data\">";
  const std::size_t from = html.find(open);
  const std::size_t to = html.find("</script>", from);
  if (from == std::string::npos || to == std::string::npos) return nullptr;
  return nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
}

inline std::vector<uint16_t> base64Words(const std::string& text) {
  std::vector<unsigned char> bytes;
  uint32_t acc = 0;
  int bits = 0;
  for (char ch : text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const std::size_t v = alphabet.find(ch);
    if (v == std::string::npos) continue;  // '=' padding
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<unsigned char>((acc >> bits) & 0xffu));
    }
  }
  std::vector<uint16_t> words(bytes.size() / 2);
  for (std::size_t i = 0; i < words.size(); ++i) {
    words[i] = static_cast<uint16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
  }
  return words;
}

inline double halfValue(uint16_t h) {
  const double sign = (h & 0x8000) ? -1.0 : 1.0;
  const int e = (h >> 10) & 31, m = h & 1023;
  if (e == 0) return sign * m * std::ldexp(1.0, -24);
  if (e == 31) return m ? NAN : sign * INFINITY;
  return sign * (1.0 + m / 1024.0) * std::ldexp(1.0, e - 15);
}

/// A packed array's values, as the page decodes them.
inline std::vector<double> decoded(const nlohmann::json& packed) {
  const std::vector<uint16_t> w = base64Words(packed.at("data").get<std::string>());
  std::vector<double> out(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (packed.at("encoding") == "float16") {
      out[i] = halfValue(w[i]) * packed.at("scale").get<double>();
    } else {
      const double lo = packed.at("lo"), hi = packed.at("hi");
      out[i] = w[i] == 65535 ? NAN : lo + w[i] * (hi - lo) / 65534.0;
    }
  }
  return out;
}

/// How far a float16-packed value may be from the file's: half a half's ulp
/// (2^-11 relative) above 2^-14 x scale, half a subnormal step below, and the
/// float32 division by the scale (2^-24 relative).
inline double halfTolerance(double value, double scale) {
  return std::ldexp(std::fabs(value), -11) * (1.0 + 1e-6) + std::ldexp(scale, -25) +
         std::ldexp(std::fabs(value), -23);
}

}  // namespace tofsim::test
