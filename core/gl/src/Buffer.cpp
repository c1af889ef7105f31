#include "tofsim/gl/Buffer.h"

#include "tofsim/gl/Check.h"
#include "tofsim/util/Error.h"

namespace tofsim::gl {

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags) : bytes_(bytes) {
  TOFSIM_CHECK(bytes > 0);
  GLuint id = 0;
  glCreateBuffers(1, &id);
  handle_ = Handle<detail::deleteBuffer>(id);
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), data, flags);
  TOFSIM_GL_CHECK("glNamedBufferStorage");
}

void Buffer::upload(std::size_t offset, std::size_t bytes, const void* data) {
  TOFSIM_CHECK(offset + bytes <= bytes_);
  glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  TOFSIM_GL_CHECK("glNamedBufferSubData");
}

void Buffer::download(std::size_t offset, std::size_t bytes, void* data) const {
  TOFSIM_CHECK(offset + bytes <= bytes_);
  glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  TOFSIM_GL_CHECK("glGetNamedBufferSubData");
}

void Buffer::clear() { fill(0u); }

void Buffer::fill(uint32_t word) {
  const GLuint value = word;
  glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
  TOFSIM_GL_CHECK("glClearNamedBufferData");
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

void Buffer::bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
  glBindBufferRange(target, index, id(), static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes));
}

}  // namespace tofsim::gl
