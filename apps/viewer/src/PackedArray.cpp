#include "PackedArray.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace tofsim::viewer {

uint16_t toHalf(float value) {
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  const auto sign = static_cast<uint16_t>((bits >> 16) & 0x8000u);
  const uint32_t magnitude = bits & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) {  // infinity or NaN
    return static_cast<uint16_t>(sign | (magnitude > 0x7f800000u ? 0x7e00u : 0x7c00u));
  }
  if (magnitude >= 0x477ff000u) return static_cast<uint16_t>(sign | 0x7c00u);  // >= 65520
  if (magnitude < 0x38800000u) {  // below 2^-14: a subnormal half, steps of 2^-24
    const float steps = std::bit_cast<float>(magnitude) * 16777216.0f;  // exact: a power of 2
    return static_cast<uint16_t>(sign | static_cast<uint32_t>(std::nearbyint(steps)));
  }
  const uint32_t exponent = ((magnitude >> 23) & 0xffu) - 127u + 15u;
  const uint32_t mantissa = magnitude & 0x7fffffu;
  uint32_t half = (exponent << 10) | (mantissa >> 13);
  const uint32_t rest = mantissa & 0x1fffu;
  // Round to nearest even; a carry into the exponent is the right result.
  if (rest > 0x1000u || (rest == 0x1000u && (half & 1u))) ++half;
  return static_cast<uint16_t>(sign | half);
}

std::string base64(const void* bytes, std::size_t count) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* in = static_cast<const unsigned char*>(bytes);
  std::string out;
  out.reserve((count + 2) / 3 * 4);
  for (std::size_t i = 0; i < count; i += 3) {
    const uint32_t b0 = in[i], b1 = i + 1 < count ? in[i + 1] : 0u,
                   b2 = i + 2 < count ? in[i + 2] : 0u;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(triple >> 18) & 63u];
    out += kAlphabet[(triple >> 12) & 63u];
    out += i + 1 < count ? kAlphabet[(triple >> 6) & 63u] : '=';
    out += i + 2 < count ? kAlphabet[triple & 63u] : '=';
  }
  return out;
}

namespace {

std::string base64Of(const std::vector<uint16_t>& words) {
  std::vector<unsigned char> bytes(words.size() * 2);
  for (std::size_t i = 0; i < words.size(); ++i) {  // little-endian on every host
    bytes[2 * i] = static_cast<unsigned char>(words[i] & 0xffu);
    bytes[2 * i + 1] = static_cast<unsigned char>(words[i] >> 8);
  }
  return base64(bytes.data(), bytes.size());
}

}  // namespace

nlohmann::json packFloat16(const std::vector<float>& values) {
  float largest = 0.0f;
  for (float v : values) {
    if (std::isfinite(v)) largest = std::max(largest, std::fabs(v));
  }
  const double scale = largest > 0.0f ? static_cast<double>(largest) / 60000.0 : 1.0;
  std::vector<uint16_t> halves(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    halves[i] = toHalf(static_cast<float>(static_cast<double>(values[i]) / scale));
  }
  return {{"encoding", "float16"}, {"scale", scale}, {"data", base64Of(halves)}};
}

nlohmann::json packUint16(const std::vector<float>& values) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (float v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) lo = hi = 0.0f;
  const double range = static_cast<double>(hi) - lo;
  std::vector<uint16_t> words(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      words[i] = 65535;
      continue;
    }
    const double q = range > 0.0 ? (values[i] - lo) / range * 65534.0 : 0.0;
    words[i] = static_cast<uint16_t>(std::lround(q));
  }
  return {{"encoding", "uint16"}, {"lo", lo}, {"hi", hi}, {"data", base64Of(words)}};
}

}  // namespace tofsim::viewer
