// The OpenGL side of the render tests: one headless context per test program, and pictures
// drawn with a test's own shaders.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/gl/gl_context.hpp"
#include "render/gl/gl_objects.hpp"

namespace eco::test {

// Makes the process's headless OpenGL context current (created on first use).
inline void useHeadlessGl() {
  static std::unique_ptr<HeadlessGl> gl = std::make_unique<HeadlessGl>();
}

// A program linked from a test's own vertex and fragment texts (Program compiles the
// product's embedded shaders only). A stage that does not compile leaves it unlinked.
inline GlName programFromTexts(const std::string& vertexText, const std::string& fragmentText) {
  GlName program(GlKind::Program, glCreateProgram());
  for (const auto& [type, text] :
       {std::pair{GL_VERTEX_SHADER, &vertexText}, std::pair{GL_FRAGMENT_SHADER, &fragmentText}}) {
    const GLuint shader = glCreateShader(type);
    const char* source = text->c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(program.id(), shader);
    glDeleteShader(shader);  // freed with the program
  }
  glLinkProgram(program.id());
  return program;
}

// The red channel (0..255) of each pixel of a square target `size` pixels wide with
// `samples` a pixel (resolved; row 0 at the top), cleared to black, after `draw` drew with
// `program` bound, an empty vertex array (vertices made from gl_VertexID), and neither
// depth test, blending nor sRGB encoding.
inline std::vector<int> redAfterDrawing(const GlName& program, int size, int samples,
                                        const std::function<void()>& draw) {
  const GlName vertexArray = makeVertexArray();
  const RenderTarget target = RenderTarget::create(size, size, 0, samples);
  target.bind();
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(program.id());
  glBindVertexArray(vertexArray.id());
  draw();
  const Image image = readPixels(target);
  std::vector<int> red;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) red.push_back(image.rgba[i]);
  return red;
}

}  // namespace eco::test
