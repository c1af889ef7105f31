#include "tofsim/gl/Framebuffer.h"

#include <string>

#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Texture.h"
#include "tofsim/util/Error.h"

namespace tofsim::gl {

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  handle_ = Handle<detail::deleteFramebuffer>(id);
}

void Framebuffer::attachColor(int index, const Texture& texture, int layer) {
  const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index);
  if (layer >= 0) {
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), 0, layer);
  } else {
    glNamedFramebufferTexture(id(), attachment, texture.id(), 0);
  }
  drawBuffers_.push_back(attachment);
}

void Framebuffer::attachDepth(const Texture& texture, int layer) {
  if (layer >= 0) {
    glNamedFramebufferTextureLayer(id(), GL_DEPTH_ATTACHMENT, texture.id(), 0, layer);
  } else {
    glNamedFramebufferTexture(id(), GL_DEPTH_ATTACHMENT, texture.id(), 0);
  }
}

void Framebuffer::finish(const char* what) {
  glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(drawBuffers_.size()),
                                drawBuffers_.data());
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  TOFSIM_CHECK_MSG(status == GL_FRAMEBUFFER_COMPLETE,
                   std::string(what) + ": framebuffer incomplete, status " + std::to_string(status));
  TOFSIM_GL_CHECK(what);
}

void Framebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }

VertexArray::VertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  handle_ = Handle<detail::deleteVertexArray>(id);
}

void VertexArray::setVertexBuffer(const Buffer& buffer, std::size_t strideBytes) {
  glVertexArrayVertexBuffer(id(), 0, buffer.id(), 0, static_cast<GLsizei>(strideBytes));
}

void VertexArray::setElementBuffer(const Buffer& buffer) {
  glVertexArrayElementBuffer(id(), buffer.id());
}

void VertexArray::setFloatAttribute(unsigned index, int components, std::size_t offsetBytes) {
  glEnableVertexArrayAttrib(id(), index);
  glVertexArrayAttribFormat(id(), index, components, GL_FLOAT, GL_FALSE,
                            static_cast<GLuint>(offsetBytes));
  glVertexArrayAttribBinding(id(), index, 0);
}

}  // namespace tofsim::gl
