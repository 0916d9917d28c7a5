#include "render/gl/shader.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gl_support.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/scene/shadow_cascades.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(Shader, EveryEmbeddedProgramCompilesInEachVariant) {
  test::useHeadlessGl();
  EXPECT_NO_THROW(Program({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}}));
  EXPECT_NO_THROW(Program({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}},
                          {"SHADOW_PASS"}));
  EXPECT_NO_THROW(
      Program({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}}, {"BAKE"}));
  EXPECT_NO_THROW(
      Program({{GL_VERTEX_SHADER, "impostor.vert"}, {GL_FRAGMENT_SHADER, "impostor.frag"}}));
  EXPECT_NO_THROW(
      Program({{GL_VERTEX_SHADER, "terrain.vert"}, {GL_FRAGMENT_SHADER, "terrain.frag"}}));
  EXPECT_NO_THROW(Program({{GL_VERTEX_SHADER, "sky.vert"}, {GL_FRAGMENT_SHADER, "sky.frag"}}));
}

TEST(Shader, ACompileErrorNamesTheFileAndTheLog) {
  test::useHeadlessGl();
  try {
    Program({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}},
            {"BROKEN\n#error deliberately broken"});
    FAIL() << "expected a compile error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("does not compile"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Program({{GL_VERTEX_SHADER, "missing.vert"}}), std::runtime_error);
}

// The samples of each pixel of a target of `samples` that coverageMask (common.glsl) keeps
// for a surface of coverage `alpha`, drawn over the whole target once for each of `seeds`
// (surfaces one behind the other): the share of each pixel's samples covered.
std::vector<double> coveredShares(int samples, float alpha, const std::vector<int>& seeds) {
  const GlName program = test::programFromTexts(
      R"(#version 450 core
    const vec2 corners[3] = vec2[](vec2(-1, -1), vec2(3, -1), vec2(-1, 3));
    void main() { gl_Position = vec4(corners[gl_VertexID], 0, 1); })",
      fmt::format("#version 450 core\n#define SHADOW_CASCADES {}\n#define FRAGMENT_STAGE\n",
                  kShadowCascades) +
          std::string(embeddedShaderSource("common.glsl")) + R"(
    uniform float uAlpha;
    uniform int uSeed;
    out vec4 colour;
    void main() {
      int mask = coverageMask(uAlpha, uint(uSeed));
      if (mask == 0) discard;
      gl_SampleMask[0] = mask;
      colour = vec4(1.0);
    })");
  GLint linked = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
  EXPECT_TRUE(linked);
  glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "uAlpha"), alpha);
  const std::vector<int> red = test::redAfterDrawing(program, 64, samples, [&] {
    for (int seed : seeds) {
      glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "uSeed"), seed);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  });
  std::vector<double> shares;
  for (int value : red) shares.push_back(value / 255.0);
  return shares;
}

double meanOf(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// The hashed alpha test sample by sample (coverageMask). One sample a pixel: each pixel is
// covered or not, alpha's share of them. Four: each pixel takes the floor or the ceiling of
// 4 alpha of its samples (stratified), alpha's share on average, so a half-covered texel
// is half of every pixel. Two surfaces one behind the other cover their samples
// independently: 1 - (1 - a)^2 of them, not a's as with one threshold for both.
TEST(Shader, TheAlphaTestKeepsEachSampleByItsOwnThreshold) {
  test::useHeadlessGl();
  ASSERT_GE(maxSamples(), 4);
  const double tolerance = 1.5 / 255.0;  // the resolve's rounding to 8 bits
  // The pixels whose share is none of `allowed`.
  const auto others = [&](const std::vector<double>& shares, std::vector<double> allowed) {
    return std::count_if(shares.begin(), shares.end(), [&](double share) {
      return std::none_of(allowed.begin(), allowed.end(),
                          [&](double a) { return std::abs(share - a) < tolerance; });
    });
  };
  const std::vector<double> whole = coveredShares(1, 0.3f, {1});
  EXPECT_EQ(others(whole, {0.0, 1.0}), 0);
  EXPECT_NEAR(meanOf(whole), 0.3, 0.03);
  EXPECT_EQ(others(coveredShares(4, 0.5f, {1}), {0.5}), 0);
  const std::vector<double> third = coveredShares(4, 0.3f, {1});
  EXPECT_EQ(others(third, {0.25, 0.5}), 0);
  EXPECT_NEAR(meanOf(third), 0.3, 0.02);
  EXPECT_NEAR(meanOf(coveredShares(4, 0.5f, {1, 2})), 0.75, 0.03);
  EXPECT_NEAR(meanOf(coveredShares(1, 0.5f, {1, 2})), 0.75, 0.03);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace eco
