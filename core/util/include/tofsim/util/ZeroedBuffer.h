#pragma once
// A large buffer of trivially copyable values that starts zero and is
// resident, for the CPU renderer's per-pixel accumulators (hundreds of MB at
// a demo's size): anonymous memory from mmap, faulted in writable in one
// call (MADV_POPULATE_WRITE) when it is made. Their first touch was a
// read-modify-write scattered over the gather (the shared zero page mapped,
// then copied on the write: two faults per 4 KiB page), which cost the CPU
// gather with the pixel footprint half its time.

#include <cstddef>
#include <type_traits>
#include <utility>

namespace tofsim::util {

namespace detail {
void* mapZeroed(std::size_t bytes);  ///< throws std::bad_alloc
void unmap(void* p, std::size_t bytes) noexcept;
}  // namespace detail

template <typename T>
class ZeroedBuffer {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  ZeroedBuffer() = default;
  explicit ZeroedBuffer(std::size_t count)
      : data_(count ? static_cast<T*>(detail::mapZeroed(count * sizeof(T))) : nullptr),
        size_(count) {}
  ~ZeroedBuffer() { detail::unmap(data_, size_ * sizeof(T)); }
  ZeroedBuffer(ZeroedBuffer&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  ZeroedBuffer& operator=(ZeroedBuffer&& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    return *this;
  }
  ZeroedBuffer(const ZeroedBuffer&) = delete;
  ZeroedBuffer& operator=(const ZeroedBuffer&) = delete;

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace tofsim::util
