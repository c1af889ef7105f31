#include "NpyHeader.h"

#include <bit>
#include <cctype>
#include <cstdint>
#include <limits>

#include "tofsim/util/Error.h"

namespace tofsim::io::detail {

static_assert(std::endian::native == std::endian::little, "npy I/O assumes a little-endian host");

namespace {

constexpr std::string_view kMagic = "\x93NUMPY";

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw InputError(FileLoc{file}, "", "not a float32 .npy file: " + message);
}

std::string shapeTuple(const NpyShape& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(shape[i]);
  }
  if (shape.size() == 1) s += ",";
  return s + ")";
}

/// Position just after "'key':" (and any spaces) in dict, or npos.
std::size_t valueStart(std::string_view dict, std::string_view key) {
  for (const char quote : {'\'', '"'}) {
    const std::string quoted = std::string(1, quote) + std::string(key) + quote;
    std::size_t pos = dict.find(quoted);
    if (pos == std::string_view::npos) continue;
    pos += quoted.size();
    while (pos < dict.size() && dict[pos] == ' ') ++pos;
    if (pos >= dict.size() || dict[pos] != ':') return std::string_view::npos;
    ++pos;
    while (pos < dict.size() && dict[pos] == ' ') ++pos;
    return pos;
  }
  return std::string_view::npos;
}

std::string parseDescr(std::string_view dict, const std::string& file) {
  const std::size_t pos = valueStart(dict, "descr");
  if (pos == std::string_view::npos || pos >= dict.size()) fail(file, "header has no 'descr'");
  const char quote = dict[pos];
  const std::size_t end = dict.find(quote, pos + 1);
  if ((quote != '\'' && quote != '"') || end == std::string_view::npos) {
    fail(file, "header 'descr' is not a simple dtype string");
  }
  return std::string(dict.substr(pos + 1, end - pos - 1));
}

bool parseFortranOrder(std::string_view dict, const std::string& file) {
  const std::size_t pos = valueStart(dict, "fortran_order");
  if (pos == std::string_view::npos) fail(file, "header has no 'fortran_order'");
  if (dict.substr(pos, 4) == "True") return true;
  if (dict.substr(pos, 5) == "False") return false;
  fail(file, "header 'fortran_order' is neither True nor False");
}

NpyShape parseShape(std::string_view dict, const std::string& file) {
  std::size_t pos = valueStart(dict, "shape");
  if (pos == std::string_view::npos || pos >= dict.size() || dict[pos] != '(') {
    fail(file, "header has no 'shape' tuple");
  }
  const std::size_t end = dict.find(')', pos);
  if (end == std::string_view::npos) fail(file, "header 'shape' tuple is not closed");
  NpyShape shape;
  for (++pos; pos < end;) {
    const char c = dict[pos];
    if (c == ' ' || c == ',') {
      ++pos;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t value = 0;
      for (; pos < end && std::isdigit(static_cast<unsigned char>(dict[pos])); ++pos) {
        const std::size_t digit = static_cast<std::size_t>(dict[pos] - '0');
        if (value > (std::numeric_limits<std::size_t>::max() - digit) / 10) {
          fail(file, "shape dimension too large");
        }
        value = value * 10 + digit;
      }
      shape.push_back(value);
    } else {
      fail(file, "header 'shape' holds something other than integers");
    }
  }
  return shape;
}

}  // namespace

std::string encodeNpyHeader(const NpyShape& shape) {
  std::string dict =
      "{'descr': '<f4', 'fortran_order': False, 'shape': " + shapeTuple(shape) + ", }";
  const std::size_t preamble = kMagic.size() + 2 + 2;
  const std::size_t unpadded = preamble + dict.size() + 1;  // + '\n'
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  TOFSIM_CHECK(dict.size() <= 0xFFFF);
  std::string out(kMagic);
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(dict.size() & 0xFF);
  out += static_cast<char>(dict.size() >> 8);
  return out + dict;
}

NpyHeaderInfo decodeNpyHeader(std::string_view prefix, const std::string& file,
                              bool allowFloat64) {
  if (prefix.size() < 10 || prefix.substr(0, kMagic.size()) != kMagic) {
    fail(file, "bad magic (expected \\x93NUMPY)");
  }
  const auto byte = [&](std::size_t i) { return static_cast<std::size_t>(uint8_t(prefix[i])); };
  const std::size_t major = byte(6);
  const std::size_t minor = byte(7);
  std::size_t headerLen = 0;
  std::size_t lenBytes = 0;
  if (major == 1 && minor == 0) {
    lenBytes = 2;
    headerLen = byte(8) | byte(9) << 8;
  } else if (major == 2 && minor == 0) {
    lenBytes = 4;
    if (prefix.size() < 12) fail(file, "truncated header");
    headerLen = byte(8) | byte(9) << 8 | byte(10) << 16 | byte(11) << 24;
  } else {
    fail(file, "unsupported version " + std::to_string(major) + "." + std::to_string(minor) +
                   " (supported: 1.0, 2.0)");
  }
  const std::size_t dictStart = 8 + lenBytes;
  if (prefix.size() < dictStart + headerLen) fail(file, "truncated header");
  const std::string_view dict = prefix.substr(dictStart, headerLen);

  const std::string descr = parseDescr(dict, file);
  const bool float64 = allowFloat64 && descr == "<f8";
  if (descr != "<f4" && !float64) {
    fail(file, "dtype '" + descr + "' is not supported (need '<f4', float32" +
                   (allowFloat64 ? std::string(", or '<f8', float64)") : std::string(")")));
  }
  if (parseFortranOrder(dict, file)) fail(file, "fortran_order True is not supported (need C order)");
  return NpyHeaderInfo{parseShape(dict, file), dictStart + headerLen, float64};
}

std::size_t checkedElementCount(const NpyShape& shape, const std::string& file) {
  std::size_t n = 1;
  for (const std::size_t d : shape) {
    if (d != 0 && n > std::numeric_limits<std::size_t>::max() / sizeof(float) / d) {
      throw InputError(FileLoc{file}, "", "npy shape is too large");
    }
    n *= d;
  }
  return n;
}

}  // namespace tofsim::io::detail
