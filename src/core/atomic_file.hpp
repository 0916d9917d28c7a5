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
#include <future>
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

// Commits AtomicFiles on another thread, one after the other in the order handed over: what
// is left of a file once its bytes are written -- waiting for the disk to hold them (fsync)
// and the rename into place -- overlaps the caller's next work (a run's next years, where a
// valley run's checkpoints had waited 5 s for the disk). A file fails as its commit()
// would; the files handed over after a failed one are not renamed into place either, and
// the error is rethrown by the next commit() that finds it or by wait().
class BackgroundCommits {
 public:
  BackgroundCommits() = default;
  BackgroundCommits(const BackgroundCommits&) = delete;
  BackgroundCommits& operator=(const BackgroundCommits&) = delete;
  // Waits for the files still being committed; an error then is not rethrown (the owner is
  // unwinding from one of its own, or did not ask).
  ~BackgroundCommits();

  // Hands over a file whose bytes are all written.
  void commit(AtomicFile file);
  // Returns once every file handed over is in place; rethrows the first failure.
  void wait();

 private:
  std::future<void> last_;  // the last file's commit, which waits for the one before
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
