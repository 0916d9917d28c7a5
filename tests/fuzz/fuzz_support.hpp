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

// A folder of this process's for the inputs (in memory where /dev/shm exists: a target
// runs thousands of times a second), removed when the process ends.
class InputFolder {
 public:
  InputFolder() {
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm")
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    path_ = base / ("ecoforest-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~InputFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The bytes as a file of this name in the input folder.
inline std::filesystem::path inputFile(std::string_view bytes, const std::string& name) {
  static const InputFolder folder;
  const std::filesystem::path file = folder.path() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
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
