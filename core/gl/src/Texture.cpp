#include "tofsim/gl/Texture.h"

#include "tofsim/gl/Check.h"
#include "tofsim/util/Error.h"

namespace tofsim::gl {

Texture::Texture(GLenum target, int width, int height, int layers)
    : width_(width), height_(height), layers_(layers) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  handle_ = Handle<detail::deleteTexture>(id);
}

Texture Texture::create2D(GLenum internalFormat, int width, int height) {
  Texture t(GL_TEXTURE_2D, width, height, 1);
  glTextureStorage2D(t.id(), 1, internalFormat, width, height);
  TOFSIM_GL_CHECK("glTextureStorage2D");
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers) {
  Texture t(GL_TEXTURE_2D_ARRAY, width, height, layers);
  glTextureStorage3D(t.id(), 1, internalFormat, width, height, layers);
  TOFSIM_GL_CHECK("glTextureStorage3D");
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::createCube(GLenum internalFormat, int size) {
  Texture t(GL_TEXTURE_CUBE_MAP, size, size, 6);
  glTextureStorage2D(t.id(), 1, internalFormat, size, size);
  TOFSIM_GL_CHECK("glTextureStorage2D(cube)");
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::upload2D(GLenum format, GLenum type, const void* pixels) {
  glTextureSubImage2D(id(), 0, 0, 0, width_, height_, format, type, pixels);
  TOFSIM_GL_CHECK("glTextureSubImage2D");
}

void Texture::bindUnit(GLuint unit) const { glBindTextureUnit(unit, id()); }

void Texture::download(GLenum format, GLenum type, std::size_t bytes, void* out) const {
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id(), 0, format, type, static_cast<GLsizei>(bytes), out);
  TOFSIM_GL_CHECK("glGetTextureImage");
}

}  // namespace tofsim::gl
