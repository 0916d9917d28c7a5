// Output files that appear whole or not at all: data goes to a temporary name beside the
// target and is renamed into place by commit(). An AtomicFile destroyed without commit()
// removes its temporary, so a failed or interrupted export leaves nothing half-written.
#pragma once

#include <deque>
#include <filesystem>
#include <fstream>
#include <span>
#include <string_view>

namespace eco {

class AtomicFile {
 public:
  // Throws InputError if the target's folder does not exist, EnvironmentError if the
  // temporary file cannot be created there (no permission, a read-only file system).
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(AtomicFile&&) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  ~AtomicFile();

  std::ofstream& stream() { return stream_; }
  const std::filesystem::path& target() const { return target_; }
  void write(std::span<const unsigned char> bytes);
  void write(std::string_view text);
  // Flushes, checks for write errors (EnvironmentError: a full disk) and renames onto the
  // target.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool done_ = false;
};

// Several files that belong together (an OBJ with its MTL and textures): all are written to
// temporaries first and renamed only when every one of them was written.
class AtomicFileSet {
 public:
  AtomicFile& add(const std::filesystem::path& target);
  void commit();

 private:
  std::deque<AtomicFile> files_;  // a deque: references from add() stay valid
};

}  // namespace eco
