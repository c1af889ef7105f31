#pragma once
// Immutable-storage GL buffer (glNamedBufferStorage), move-only.

#include <cstddef>
#include <cstdint>

#include "tofsim/gl/Handle.h"

namespace tofsim::gl {

class Buffer {
 public:
  Buffer() = default;
  /// Allocates `bytes` bytes, initialised from `data` when not null.
  /// `flags`: GL_DYNAMIC_STORAGE_BIT etc.
  Buffer(std::size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

  std::size_t size() const { return bytes_; }
  GLuint id() const { return handle_.id(); }

  void upload(std::size_t offset, std::size_t bytes, const void* data);
  void download(std::size_t offset, std::size_t bytes, void* data) const;
  /// Sets every 32-bit word to zero.
  void clear();
  /// Sets every 32-bit word to `word` (e.g. the bits of +inf).
  void fill(uint32_t word);
  void bindBase(GLenum target, GLuint index) const;
  void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;

 private:
  Handle<detail::deleteBuffer> handle_;
  std::size_t bytes_ = 0;
};

}  // namespace tofsim::gl
