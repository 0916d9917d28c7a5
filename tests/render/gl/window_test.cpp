#include "render/gl/window.hpp"

#include <cstdlib>
#include <string>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {
namespace {

// Keeps an environment variable unset for a scope.
class WithoutVariable {
 public:
  explicit WithoutVariable(const char* name) : name_(name) {
    if (const char* value = std::getenv(name)) saved_ = value, had_ = true;
    unsetenv(name);
  }
  ~WithoutVariable() {
    if (had_) setenv(name_, saved_.c_str(), 1);
  }

 private:
  const char* name_;
  std::string saved_;
  bool had_ = false;
};

TEST(Window, WithoutADisplayItIsTheEnvironmentsError) {
  const WithoutVariable display("DISPLAY"), wayland("WAYLAND_DISPLAY");
  EXPECT_THROW(Window("test", {64, 48}, "`test`", "no display needed"), EnvironmentError);
}

// Needs a display: ctest runs it under xvfb-run (tests/render/CMakeLists.txt).
TEST(Window, OpensDrawsAFrameAndClosesItself) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (ctest runs this under xvfb-run)";
  for (int round = 0; round < 2; ++round) {  // a second window after the first is gone
    Window window("test", {96, 64}, "`test`", "no display needed");
    EXPECT_FALSE(window.shouldClose());
    const ViewInput& input = window.beginFrame();
    EXPECT_TRUE(input.pressed.empty());
    const FrameSize size = window.framebufferSize();
    EXPECT_EQ(size, (FrameSize{96, 64}));
    // The second window shows a target of half its size, magnified (view's dynamic
    // resolution).
    const RenderTarget target =
        RenderTarget::create(size.width / (round + 1), size.height / (round + 1));
    target.bind();
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    window.present(target);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_GE(window.seconds(), 0.0);
  }
}

}  // namespace
}  // namespace eco
