// The OpenGL side of the render tests: one headless context per test program.
#pragma once

#include <memory>

#include "render/gl/gl_context.hpp"

namespace eco::test {

// Makes the process's headless OpenGL context current (created on first use).
inline void useHeadlessGl() {
  static std::unique_ptr<HeadlessGl> gl = std::make_unique<HeadlessGl>();
}

}  // namespace eco::test
