#pragma once
// Immutable-storage GL textures (2D, 2D array, cube map), move-only.

#include "tofsim/gl/Handle.h"

namespace tofsim::gl {

class Texture {
 public:
  Texture() = default;
  static Texture create2D(GLenum internalFormat, int width, int height);
  static Texture create2DArray(GLenum internalFormat, int width, int height, int layers);
  static Texture createCube(GLenum internalFormat, int size);

  GLuint id() const { return handle_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }

  void setFilter(GLenum minFilter, GLenum magFilter);
  void setWrap(GLenum wrap);
  void upload2D(GLenum format, GLenum type, const void* pixels);
  void bindUnit(GLuint unit) const;
  /// Reads level 0 of a 2D texture into `out` (tightly packed rows).
  void download(GLenum format, GLenum type, std::size_t bytes, void* out) const;

 private:
  Texture(GLenum target, int width, int height, int layers);
  Handle<detail::deleteTexture> handle_;
  int width_ = 0;
  int height_ = 0;
  int layers_ = 0;
};

}  // namespace tofsim::gl
