// Ctrl-C (SIGINT) and a polite kill (SIGTERM) never leave a half-written file behind: every
// temporary that an AtomicFile or a frame sink holds open is registered here, and the
// signal handler removes them before the process exits with kExitInterrupted. A command
// that can stop cleanly on its own (a run finishes its year) asks for a graceful first
// signal instead; a second signal then cleans up and exits at once.
#pragma once

#include <atomic>
#include <filesystem>

namespace eco {

// Installs the handler for SIGINT and SIGTERM. The command line does it once, first.
void installInterruptCleanup();

// While it lives, `path` (a file, or a folder of files) is removed if the process is
// interrupted. Registrations beyond a fixed number of slots (kInterruptSlots) are silently
// not kept: the temporary is then left behind, as it would be after kill -9.
class InterruptCleanup {
 public:
  enum class Kind { file, folder };
  explicit InterruptCleanup(const std::filesystem::path& path, Kind kind = Kind::file);
  InterruptCleanup(InterruptCleanup&& other) noexcept;
  InterruptCleanup& operator=(InterruptCleanup&&) = delete;
  ~InterruptCleanup();
  // The path no longer needs removing (it was renamed into place or removed already).
  void release();

 private:
  int slot_ = -1;
};
inline constexpr int kInterruptSlots = 256;

// While it lives, the first SIGINT or SIGTERM only sets `flag`; the work checks it and
// stops where its files are complete. A second signal cleans up and exits.
class GracefulStop {
 public:
  explicit GracefulStop(std::atomic<bool>& flag);
  GracefulStop(const GracefulStop&) = delete;
  GracefulStop& operator=(const GracefulStop&) = delete;
  ~GracefulStop();
};

}  // namespace eco
