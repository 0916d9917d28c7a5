// Owning handles for OpenGL objects (moved, never copied) and the few helpers every part of
// the renderer needs: immutable buffers, textures from images, render targets, read-back.
#pragma once

#include <vector>

#include <cstdint>
#include <span>
#include <utility>

#include <epoxy/gl.h>

#include "core/image.hpp"

namespace eco {

enum class GlKind { Buffer, VertexArray, Texture, Framebuffer, Program, Query };

class GlName {
 public:
  GlName() = default;
  GlName(GlKind kind, GLuint id) : kind_(kind), id_(id) {}
  ~GlName() { reset(); }
  GlName(GlName&& other) noexcept : kind_(other.kind_), id_(std::exchange(other.id_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      kind_ = other.kind_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset();

 private:
  GlKind kind_ = GlKind::Buffer;
  GLuint id_ = 0;
};

GlName makeBuffer(const void* data, std::size_t bytes, GLbitfield flags = 0);
template <class T>
GlName makeBuffer(std::span<const T> data, GLbitfield flags = 0) {
  return makeBuffer(data.data(), data.size_bytes(), flags);
}
GlName makeVertexArray();

// A buffer that data is appended to. Where an append does not fit, the data so far moves
// into a new store of twice the size needed (the buffer's name changes: bind it again).
class AppendBuffer {
 public:
  // The offset in bytes the appended data starts at.
  std::size_t append(const void* data, std::size_t bytes);
  template <class T>
  std::size_t append(std::span<const T> data) {
    return append(data.data(), data.size_bytes());
  }
  GLuint id() const { return buffer_.id(); }
  std::size_t size() const { return size_; }

 private:
  GlName buffer_;
  std::size_t size_ = 0, capacity_ = 0;
};

// An empty 2D texture of `levels` mip levels, filtered linearly (trilinearly when
// mipmapped), clamped at the edges or repeating.
GlName makeTextureStorage(GLenum format, int width, int height, int levels = 1,
                          bool repeat = false);
// An RGBA8 texture with mipmaps from an image (row 0 at the top, as glTF's uv expects).
GlName makeTexture(const Image& image, bool repeat);
// A view of an sRGB texture's storage (every mip level) as linear RGBA8: its alpha, texel
// for texel, read without the decoding of its colour that an sRGB read costs each time on
// a software renderer. No memory of its own.
GlName makeLinearView(const GlName& srgbTexture);

// sRGB colour plus depth. The shaders write linear colour, which OpenGL encodes as sRGB
// (GL_FRAMEBUFFER_SRGB), so every target holds what a PNG or a screen expects.
// With more than one sample a pixel (multisample anti-aliasing), what is drawn goes into
// multisampled colour and depth, and resolve() averages the samples into `color`.
struct RenderTarget {
  int width = 0, height = 0;
  int samples = 1;
  GlName framebuffer;  // what draws bind
  GlName color;        // what the target shows (after resolve() when multisampled)
  // Linear RGBA8 attachments 1, 2, ... when asked for (the impostors' normals and depths).
  std::vector<GlName> extraColors;
  GlName depth;
  GlName multisampleColor, resolved;  // samples > 1: the drawn samples; `color`'s framebuffer

  // An EnvironmentError where the driver draws fewer samples than asked for;
  // kAutoSamples: samplesFor()'s choice.
  static RenderTarget create(int width, int height, int extraColors = 0, int samples = 1);
  void bind() const;
  void resolve() const;
};

// The most samples a pixel this OpenGL draws (GL_MAX_SAMPLES; 4 on llvmpipe).
int maxSamples();

// Whether this OpenGL draws on the CPU (Mesa's llvmpipe and softpipe, SwiftShader).
bool isSoftwareRasteriser();

// `--antialias auto`: 4 samples a pixel where a GPU draws them, nearly free, and none on a
// software rasteriser, where 4 samples cost 3-4 times the frame (docs/rendering.md).
inline constexpr int kAutoSamples = 0;
// The samples a pixel to draw with: kAutoSamples as above (fewer where the driver draws
// fewer), any other count as asked.
int samplesFor(int requested);

// Reads the colour attachment of the bound framebuffer; row 0 of the image is the top row.
Image readPixels(int width, int height, GLenum attachment = GL_COLOR_ATTACHMENT0);

// The colour of a target (resolved, and bound for it): what it shows, row 0 at the top.
Image readPixels(const RenderTarget& target);
// The inverse: an image (row 0 at the top) of the target's size into its colour (a target
// of one sample).
void writePixels(const RenderTarget& target, const Image& image);

// Throws std::runtime_error naming `where` if OpenGL reported an error.
void checkGl(const char* where);

}  // namespace eco
