#include "render/gl/shader.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/scene/shadow_cascades.hpp"

namespace eco {
namespace {

std::string infoLog(GLuint object, bool program) {
  GLint length = 0;
  program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
          : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  program ? glGetProgramInfoLog(object, length, nullptr, log.data())
          : glGetShaderInfoLog(object, length, nullptr, log.data());
  return log;
}

std::string_view requireSource(std::string_view file) {
  std::string_view source = embeddedShaderSource(file);
  if (source.empty()) throw std::runtime_error(fmt::format("no embedded shader '{}'", file));
  return source;
}

}  // namespace

Program::Program(std::initializer_list<ShaderStage> stages, const std::vector<std::string>& defines,
                 const std::vector<const char*>& feedback) {
  // The frame's uniform block (common.glsl) holds an array of the shadow cascades.
  std::string header =
      fmt::format("#version 450 core\n#define SHADOW_CASCADES {}\n", kShadowCascades);
  for (const std::string& define : defines) header += "#define " + define + "\n";
  const std::string_view common = requireSource("common.glsl");

  GLuint program = glCreateProgram();
  program_ = GlName(GlKind::Program, program);
  std::vector<GLuint> shaders;
  for (const ShaderStage& stage : stages) {
    // #line resets numbering so that compiler messages point into the stage's own file.
    const char* stageDefine =
        stage.type == GL_FRAGMENT_SHADER ? "#define FRAGMENT_STAGE\n" : "#define VERTEX_STAGE\n";
    std::string text = header + stageDefine + std::string(common) + "\n#line 1\n" +
                       std::string(requireSource(stage.file));
    GLuint shader = glCreateShader(stage.type);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      std::string log = infoLog(shader, false);
      glDeleteShader(shader);
      throw std::runtime_error(fmt::format("shader {} does not compile:\n{}", stage.file, log));
    }
    glAttachShader(program, shader);
    shaders.push_back(shader);
  }
  if (!feedback.empty())
    glTransformFeedbackVaryings(program, static_cast<GLsizei>(feedback.size()), feedback.data(),
                                GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(program);
  for (GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
    throw std::runtime_error(
        fmt::format("shader program does not link:\n{}", infoLog(program, true)));
}

void Program::set(const char* name, float value) const {
  glProgramUniform1f(id(), glGetUniformLocation(id(), name), value);
}
void Program::set(const char* name, int value) const {
  glProgramUniform1i(id(), glGetUniformLocation(id(), name), value);
}
void Program::set(const char* name, glm::vec2 value) const {
  glProgramUniform2fv(id(), glGetUniformLocation(id(), name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, glm::vec3 value) const {
  glProgramUniform3fv(id(), glGetUniformLocation(id(), name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, glm::vec4 value) const {
  glProgramUniform4fv(id(), glGetUniformLocation(id(), name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat4& value) const {
  glProgramUniformMatrix4fv(id(), glGetUniformLocation(id(), name), 1, GL_FALSE,
                            glm::value_ptr(value));
}

}  // namespace eco
