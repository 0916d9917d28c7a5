#include "render/gl/shader.hpp"

#include <gtest/gtest.h>

#include "gl_support.hpp"
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

}  // namespace
}  // namespace eco
