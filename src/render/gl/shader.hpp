// GLSL programs from the shaders compiled into the binary (src/render/shaders/). Every
// stage gets "#version 450 core", the given #defines and common.glsl before its own text,
// so the wind, lighting and dithering code exists once.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gl/gl_objects.hpp"

namespace eco {

// The text of an embedded shader file; empty if there is none of that name.
std::string_view embeddedShaderSource(std::string_view name);

struct ShaderStage {
  GLenum type;            // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
  std::string_view file;  // a file of src/render/shaders/
};

class Program {
 public:
  Program() = default;
  // Throws std::runtime_error with the compiler's log on failure. `defines` are names
  // ("SHADOW_PASS") or "NAME VALUE". `feedback` names vertex outputs to capture with
  // transform feedback (interleaved), for tests.
  Program(std::initializer_list<ShaderStage> stages, const std::vector<std::string>& defines = {},
          const std::vector<const char*>& feedback = {});

  GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }
  // Uniform setters; a uniform the compiler optimised away is ignored.
  void set(const char* name, float value) const;
  void set(const char* name, int value) const;
  void set(const char* name, glm::vec2 value) const;
  void set(const char* name, glm::vec3 value) const;
  void set(const char* name, glm::vec4 value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  GlName program_;
};

}  // namespace eco
