#include "render/gl/gl_context.hpp"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl_support.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(HeadlessGl, GivesAnOpenGl45CoreContextWithoutADisplay) {
  test::useHeadlessGl();
  EXPECT_GE(epoxy_gl_version(), 45);
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_NE(glDescription().find("|"), std::string::npos);
}

}  // namespace
}  // namespace eco
