// What every fuzz target shares (docs/robustness.md). A target takes bytes, hands them to
// one of ecoforest's readers as a file, and returns normally whatever the bytes are: an
// InputError or EnvironmentError is the reader doing its job. Anything else -- another
// exception, a crash, a sanitizer report, a hang -- is a finding.
#pragma once

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace eco::fuzz {

// The bytes as a file with this extension, in a folder of this process's (in memory where
// /dev/shm exists: a target runs thousands of times a second).
inline std::filesystem::path inputFile(std::string_view bytes, const std::string& name) {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path base =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    std::filesystem::path f = base / ("ecoforest-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  const std::filesystem::path file = folder / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(),
                                                                static_cast<std::streamsize>(bytes.size()));
  return file;
}

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs a reader; the errors it is meant to throw are not findings.
template <class F>
void expectingInputErrors(F&& read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const EnvironmentError&) {
  }
}

}  // namespace eco::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
