#include "render/gl/gl_objects.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "gl_support.hpp"

namespace eco {

TEST(GlObjects, WritePixelsIsTheInverseOfReadPixels) {
  test::useHeadlessGl();
  Image image(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) image.set(x, y, {x / 7.0f, y / 5.0f, 0.5f, 1.0f});
  const RenderTarget target = RenderTarget::create(7, 5);
  writePixels(target, image);
  EXPECT_EQ(readPixels(target).rgba, image.rgba);
}

// The linear view of an sRGB texture holds its alpha at every mip level, byte for byte, and
// samples as the texture does (the same filters and wrapping); its colour is the texture's
// bytes undecoded.
TEST(GlObjects, ALinearViewOfAnSrgbTextureHoldsItsAlphaAtEveryLevel) {
  test::useHeadlessGl();
  Image image(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      image.set(x, y, {0.2f, x / 16.0f, 0.7f, ((x * 7 + y * 3) % 11) / 10.0f});
  const GlName texture = makeTexture(image, true);
  const GlName view = makeLinearView(texture);
  GLint format = 0;
  glGetTextureLevelParameteriv(view.id(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_RGBA8);
  for (int level = 0; level < 5; ++level) {
    const int w = 16 >> level, h = std::max(8 >> level, 1);
    std::vector<std::uint8_t> a(std::size_t{4} * w * h), b(a.size());
    glGetTextureImage(texture.id(), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(a.size()), a.data());
    glGetTextureImage(view.id(), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(b.size()), b.data());
    EXPECT_EQ(a, b) << "level " << level;  // the stored bytes: alpha, and colour undecoded
  }
  for (GLenum parameter :
       {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) {
    GLint ofTexture = 0, ofView = 0;
    glGetTextureParameteriv(texture.id(), parameter, &ofTexture);
    glGetTextureParameteriv(view.id(), parameter, &ofView);
    EXPECT_EQ(ofView, ofTexture) << parameter;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

namespace {

// A white triangle over the lower-left half of a square target (its hypotenuse the diagonal
// from the top-left to the bottom-right corner), read back as the red channel.
std::vector<int> drawHalfSquare(int size, int samples) {
  const GlName program = test::programFromTexts(R"(#version 450
    const vec2 corners[3] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1));
    void main() { gl_Position = vec4(corners[gl_VertexID], 0, 1); })",
                                                R"(#version 450
    out vec4 colour;
    void main() { colour = vec4(1); })");
  return test::redAfterDrawing(program, size, samples, [] { glDrawArrays(GL_TRIANGLES, 0, 3); });
}

}  // namespace

// One sample a pixel: every pixel is in or out (the staircase along the diagonal). Four:
// the pixels the diagonal crosses take part of the colour, the rest stay whole.
TEST(GlObjects, AMultisampledTargetResolvesEdgesToPartialCoverage) {
  test::useHeadlessGl();
  ASSERT_GE(maxSamples(), 4);
  constexpr int kSize = 16;
  const auto partial = [](const std::vector<int>& red) {
    return std::count_if(red.begin(), red.end(), [](int v) { return v > 0 && v < 255; });
  };
  const std::vector<int> aliased = drawHalfSquare(kSize, 1);
  const std::vector<int> smooth = drawHalfSquare(kSize, 4);
  EXPECT_EQ(partial(aliased), 0);
  EXPECT_GE(partial(smooth), kSize - 2);  // the diagonal crosses one pixel a row
  EXPECT_LE(partial(smooth), 2 * kSize);
  // Far from the edge both agree: the top-right corner out, the bottom-left one in (row 0 of
  // the image is the top).
  for (const std::vector<int>* red : {&aliased, &smooth}) {
    EXPECT_EQ((*red)[kSize - 1], 0);
    EXPECT_EQ((*red)[(kSize - 1) * kSize], 255);
  }
}

TEST(GlObjects, MoreSamplesThanTheDriverDrawsIsAnEnvironmentError) {
  test::useHeadlessGl();
  EXPECT_THROW(RenderTarget::create(8, 8, 0, 2 * maxSamples()), EnvironmentError);
}

// --antialias auto: none on a software rasteriser (the tests run on llvmpipe), where
// samples cost 3-4 times the frame; a count asked for is kept.
TEST(GlObjects, AutomaticAntialiasingDrawsNoSamplesOnASoftwareRasteriser) {
  test::useHeadlessGl();
  EXPECT_EQ(samplesFor(1), 1);
  EXPECT_EQ(samplesFor(4), 4);
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer.find("llvmpipe") == std::string::npos)
    GTEST_SKIP() << "the OpenGL is not llvmpipe: " << renderer;
  EXPECT_TRUE(isSoftwareRasteriser());
  EXPECT_EQ(samplesFor(kAutoSamples), 1);
  EXPECT_EQ(RenderTarget::create(8, 8, 0, kAutoSamples).samples, 1);
}

}  // namespace eco
