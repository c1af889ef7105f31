#pragma once
// Arrays packed for the viewer's page: base64 text of little-endian 16-bit
// values, with what the page needs to turn them back into numbers.
//   float16: value = half * scale. Radiance spans decades (the page tone-maps
//     it on a log scale): a half keeps 11 significant bits (relative error at
//     most 2^-11) from scale * 2^-14 up, and scale * 2^-24 steps below that.
//   uint16: value = lo + q * (hi - lo) / 65534, 65535 = NaN. A sensor map is
//     drawn between its lowest and highest finite value; 65534 steps of that
//     range keep every value within (hi - lo) / 131068 of the file's.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace tofsim::viewer {

/// IEEE 754 binary16 of `value`, rounded to nearest even; overflow gives
/// infinity, NaN stays NaN.
uint16_t toHalf(float value);

/// RFC 4648 base64 of `bytes` bytes.
std::string base64(const void* bytes, std::size_t count);

/// {"encoding": "float16", "scale", "data"}: scale = the largest |value| /
/// 60000 (1 when all are 0), so no finite value overflows the half's 65504.
nlohmann::json packFloat16(const std::vector<float>& values);

/// {"encoding": "uint16", "lo", "hi", "data"} over the finite values (lo = hi
/// = 0 when none is finite).
nlohmann::json packUint16(const std::vector<float>& values);

}  // namespace tofsim::viewer
