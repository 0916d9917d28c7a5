#include "render/gl/gl_objects.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace eco {

void GlName::reset() {
  if (!id_) return;
  switch (kind_) {
    case GlKind::Buffer:
      glDeleteBuffers(1, &id_);
      break;
    case GlKind::VertexArray:
      glDeleteVertexArrays(1, &id_);
      break;
    case GlKind::Texture:
      glDeleteTextures(1, &id_);
      break;
    case GlKind::Framebuffer:
      glDeleteFramebuffers(1, &id_);
      break;
    case GlKind::Program:
      glDeleteProgram(id_);
      break;
    case GlKind::Query:
      glDeleteQueries(1, &id_);
      break;
  }
  id_ = 0;
}

GlName makeBuffer(const void* data, std::size_t bytes, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  // Zero-sized buffers are invalid for glNamedBufferStorage; keep one byte.
  glNamedBufferStorage(id, bytes ? static_cast<GLsizeiptr>(bytes) : 1, bytes ? data : nullptr,
                       flags);
  return {GlKind::Buffer, id};
}

std::size_t AppendBuffer::append(const void* data, std::size_t bytes) {
  const std::size_t offset = size_;
  if (size_ + bytes > capacity_) {
    const std::size_t capacity = 2 * (size_ + bytes);
    GlName grown = makeBuffer(nullptr, capacity, GL_DYNAMIC_STORAGE_BIT);
    if (size_ > 0)
      glCopyNamedBufferSubData(buffer_.id(), grown.id(), 0, 0, static_cast<GLsizeiptr>(size_));
    buffer_ = std::move(grown);
    capacity_ = capacity;
  }
  if (bytes > 0)
    glNamedBufferSubData(buffer_.id(), static_cast<GLintptr>(offset),
                         static_cast<GLsizeiptr>(bytes), data);
  size_ += bytes;
  return offset;
}

GlName makeVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return {GlKind::VertexArray, id};
}

GlName makeTextureStorage(GLenum format, int width, int height, int levels, bool repeat) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, levels, format, width, height);
  const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, wrap);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return {GlKind::Texture, id};
}

GlName makeTexture(const Image& image, bool repeat) {
  int levels = 1;
  for (int size = std::max(image.width, image.height); size > 1; size /= 2) ++levels;
  GlName texture = makeTextureStorage(GL_SRGB8_ALPHA8, image.width, image.height, levels, repeat);
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.rgba.data());
  glGenerateTextureMipmap(texture.id());
  return texture;
}

GlName makeLinearView(const GlName& srgbTexture) {
  GLint levels = 0;
  glGetTextureParameteriv(srgbTexture.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  GLuint id = 0;
  glGenTextures(1, &id);  // a view takes a name never bound, so not glCreateTextures
  glTextureView(id, GL_TEXTURE_2D, srgbTexture.id(), GL_RGBA8, 0, static_cast<GLuint>(levels), 0,
                1);
  // A view has sampling parameters of its own: the texture's.
  for (GLenum parameter :
       {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) {
    GLint value = 0;
    glGetTextureParameteriv(srgbTexture.id(), parameter, &value);
    glTextureParameteri(id, parameter, value);
  }
  return {GlKind::Texture, id};
}

namespace {

GlName makeFramebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return {GlKind::Framebuffer, id};
}

void checkComplete(const GlName& framebuffer, int width, int height) {
  if (glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(fmt::format("OpenGL: incomplete {}x{} framebuffer", width, height));
}

}  // namespace

int maxSamples() {
  GLint samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return samples;
}

bool isSoftwareRasteriser() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string renderer = name ? name : "";
  for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
    if (renderer.find(software) != std::string::npos) return true;
  return false;
}

int samplesFor(int requested) {
  if (requested != kAutoSamples) return requested;
  return isSoftwareRasteriser() ? 1 : std::min(4, std::max(1, maxSamples()));
}

RenderTarget RenderTarget::create(int width, int height, int extraColors, int samples) {
  samples = samplesFor(samples);
  ECO_ASSERT(samples >= 1 && (samples == 1 || extraColors == 0),
             "samples=" << samples << " extraColors=" << extraColors);
  if (samples > maxSamples())
    throw EnvironmentError(fmt::format(
        "anti-aliasing with {} samples a pixel: this OpenGL draws at most {} ({})", samples,
        maxSamples(), reinterpret_cast<const char*>(glGetString(GL_RENDERER))));
  RenderTarget t;
  t.width = width;
  t.height = height;
  t.samples = samples;
  t.framebuffer = makeFramebuffer();
  const GLuint id = t.framebuffer.id();
  auto attach = [&](GLenum format, GLenum attachment) {
    if (samples == 1) {
      GlName texture = makeTextureStorage(format, width, height);
      glNamedFramebufferTexture(id, attachment, texture.id(), 0);
      return texture;
    }
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &texture);
    glTextureStorage2DMultisample(texture, samples, format, width, height, GL_TRUE);
    glNamedFramebufferTexture(id, attachment, texture, 0);
    return GlName(GlKind::Texture, texture);
  };
  if (samples > 1) {
    t.multisampleColor = attach(GL_SRGB8_ALPHA8, GL_COLOR_ATTACHMENT0);
    t.resolved = makeFramebuffer();
    t.color = makeTextureStorage(GL_SRGB8_ALPHA8, width, height);
    glNamedFramebufferTexture(t.resolved.id(), GL_COLOR_ATTACHMENT0, t.color.id(), 0);
    checkComplete(t.resolved, width, height);
  } else {
    t.color = attach(GL_SRGB8_ALPHA8, GL_COLOR_ATTACHMENT0);
  }
  if (extraColors > 0) {
    std::vector<GLenum> buffers{GL_COLOR_ATTACHMENT0};
    for (int k = 1; k <= extraColors; ++k) {
      buffers.push_back(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + k));
      t.extraColors.push_back(attach(GL_RGBA8, buffers.back()));
    }
    glNamedFramebufferDrawBuffers(id, static_cast<GLsizei>(buffers.size()), buffers.data());
  }
  t.depth = attach(GL_DEPTH_COMPONENT32F, GL_DEPTH_ATTACHMENT);
  checkComplete(t.framebuffer, width, height);
  return t;
}

void RenderTarget::resolve() const {
  if (samples == 1) return;
  glBlitNamedFramebuffer(framebuffer.id(), resolved.id(), 0, 0, width, height, 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, width, height);
}

Image readPixels(int width, int height, GLenum attachment) {
  Image image(width, height);
  glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // OpenGL's row 0 is the bottom one.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(image.rgba.begin() + y * row, image.rgba.begin() + (y + 1) * row,
                     image.rgba.begin() + (height - 1 - y) * row);
  return image;
}

Image readPixels(const RenderTarget& target) {
  target.resolve();
  glBindFramebuffer(GL_FRAMEBUFFER,
                    target.samples > 1 ? target.resolved.id() : target.framebuffer.id());
  Image image = readPixels(target.width, target.height);
  target.bind();
  return image;
}

void writePixels(const RenderTarget& target, const Image& image) {
  ECO_ASSERT(target.samples == 1, "samples=" << target.samples);
  ECO_ASSERT(
      image.width == target.width && image.height == target.height,
      image.width << "x" << image.height << " into " << target.width << "x" << target.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y)  // OpenGL's row 0 is the bottom one
    glTextureSubImage2D(target.color.id(), 0, 0, image.height - 1 - y, image.width, 1, GL_RGBA,
                        GL_UNSIGNED_BYTE, image.rgba.data() + y * row);
}

void checkGl(const char* where) {
  GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw std::runtime_error(fmt::format("OpenGL error 0x{:x} in {}", error, where));
}

}  // namespace eco
