// Little binary files (checkpoints): a writer that appends plain values to a byte string, a
// reader that takes them back with bounds checks, and reading a whole file.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/hash.hpp"

namespace eco {

// The bytes of a file, or nothing if it cannot be opened.
inline std::optional<std::string> readFileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class BinaryWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void putString(std::string_view text) {
    put<std::uint64_t>(text.size());
    bytes_.append(text);
  }
  template <typename T>
  void putVector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// Reading past the end sets failed() and yields zeros, so a truncated file is detected once,
// at the end, instead of at every read.
class BinaryReader {
 public:
  explicit BinaryReader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value{};
    if (!take(sizeof(T))) return value;
    std::memcpy(&value, bytes_.data() + offset_ - sizeof(T), sizeof(T));
    return value;
  }
  std::string getString() {
    const auto size = get<std::uint64_t>();
    if (!take(size)) return {};
    return std::string(bytes_.substr(offset_ - size, size));
  }
  template <typename T>
  void getVector(std::vector<T>& values) {
    const auto count = get<std::uint64_t>();
    if (count > (bytes_.size() - offset_) / sizeof(T) || !take(count * sizeof(T))) {
      failed_ = true;
      values.clear();
      return;
    }
    values.resize(count);
    // memcpy with the null data() of an empty vector is undefined, even for zero bytes.
    if (count > 0)
      std::memcpy(values.data(), bytes_.data() + offset_ - count * sizeof(T), count * sizeof(T));
  }
  bool failed() const { return failed_; }
  bool atEnd() const { return offset_ == bytes_.size(); }
  std::size_t remaining() const { return bytes_.size() - offset_; }

 private:
  bool take(std::uint64_t size) {
    if (failed_ || size > bytes_.size() - offset_) {
      failed_ = true;
      return false;
    }
    offset_ += size;
    return true;
  }
  std::string_view bytes_;
  std::size_t offset_ = 0;
  bool failed_ = false;
};

}  // namespace eco
