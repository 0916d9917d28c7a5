// Output files that appear whole or not at all: data goes to a temporary name beside the
// target and is renamed into place by commit(). Every write is checked to the last byte: a
// full disk or a failing device is an EnvironmentError naming the file and the cause, the
// temporary is removed, and nothing is renamed. commit() makes the data durable (fsync of
// the file, then of its folder after the rename), so a crash of the machine after a commit
// cannot leave an empty file under the target's name. An AtomicFile destroyed without
// commit(), or a process interrupted by Ctrl-C (core/interrupt.hpp), removes its temporary.
#pragma once

#include <deque>
#include <filesystem>
#include <span>
#include <string_view>

#include "core/interrupt.hpp"

namespace eco {

class AtomicFile {
 public:
  // Throws InputError if the target's folder does not exist, EnvironmentError if the
  // temporary file cannot be created there (no permission, a read-only file system).
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(AtomicFile&&) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  ~AtomicFile();

  const std::filesystem::path& target() const { return target_; }
  // EnvironmentError (the temporary removed) when the bytes cannot all be written.
  void write(std::span<const unsigned char> bytes);
  void write(std::string_view text);
  // Writes what is buffered, fsyncs, closes and renames onto the target.
  void commit();
  // Writes what is buffered and fsyncs, without renaming (AtomicFileSet: every file of a
  // set is complete before the first is renamed).
  void flush();

 private:
  [[noreturn]] void fail(const char* what, int error);
  void writeOut(std::string_view bytes);

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int descriptor_ = -1;
  std::string buffer_;  // small writes are gathered into 1 MiB system calls
  InterruptCleanup cleanup_;
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

// Whether a file name is that of an AtomicFile's temporary (NAME.tmp-PID-N).
bool isAtomicTemporary(std::string_view fileName);

// Creates an output folder and the folders above it; returns whether it was made (false
// when it existed). EnvironmentError naming the folder and the cause (no permission, a
// read-only file system).
bool createOutputFolder(const std::filesystem::path& folder);

// fsyncs a folder, so that a rename into it survives a crash of the machine; errors are
// ignored (some file systems cannot sync folders).
void syncFolder(const std::filesystem::path& folder);

}  // namespace eco
