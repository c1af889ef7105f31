#pragma once
// A framebuffer object with colour attachments and a depth attachment,
// move-only. Completeness is checked when finished.

#include <cstddef>
#include <vector>

#include "tofsim/gl/Handle.h"

namespace tofsim::gl {

class Texture;

class Framebuffer {
 public:
  Framebuffer();
  /// Attaches `texture` level 0 (or one layer/cube face when layer >= 0) as
  /// colour attachment `index`.
  void attachColor(int index, const Texture& texture, int layer = -1);
  void attachDepth(const Texture& texture, int layer = -1);
  /// Enables the attached colour outputs and checks completeness.
  void finish(const char* what);
  void bind() const;

  GLuint id() const { return handle_.id(); }

 private:
  Handle<detail::deleteFramebuffer> handle_;
  std::vector<GLenum> drawBuffers_;
};

class Buffer;

class VertexArray {
 public:
  VertexArray();
  GLuint id() const { return handle_.id(); }
  void bind() const { glBindVertexArray(id()); }
  /// Interleaved vertices from `buffer` at binding 0, `strideBytes` apart.
  void setVertexBuffer(const Buffer& buffer, std::size_t strideBytes);
  void setElementBuffer(const Buffer& buffer);
  /// Float attribute `index` of `components` floats at `offsetBytes` in a vertex.
  void setFloatAttribute(unsigned index, int components, std::size_t offsetBytes);

 private:
  Handle<detail::deleteVertexArray> handle_;
};

}  // namespace tofsim::gl
