#pragma once
// FNV-1a, 64 bit: a small, dependency-free checksum for batch manifests. It
// detects truncated or changed output files; it is not a cryptographic hash
// and must not be used where an adversary chooses the bytes.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace tofsim {

class Fnv1a64 {
 public:
  static constexpr uint64_t kOffsetBasis = 14695981039346656037ull;
  static constexpr uint64_t kPrime = 1099511628211ull;

  void update(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      state_ ^= p[i];
      state_ *= kPrime;
    }
  }
  void update(std::string_view text) { update(text.data(), text.size()); }
  uint64_t value() const { return state_; }

 private:
  uint64_t state_ = kOffsetBasis;
};

/// FNV-1a 64 of a whole file, streamed. Throws InputError when unreadable.
uint64_t fnv1a64File(const std::filesystem::path& path);

/// 16 lower-case hex digits.
std::string hex64(uint64_t value);

}  // namespace tofsim
