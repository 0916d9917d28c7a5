// Reading back a glTF file a test wrote (.glb or .gltf), for the suites that export one.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

namespace eco::test {

inline tinygltf::Model loadGltf(const std::filesystem::path& file) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = file.extension() == ".glb"
                      ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                      : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
  EXPECT_TRUE(ok) << file << ": " << error;
  return model;
}

}  // namespace eco::test
