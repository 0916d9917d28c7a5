// One run at a time in a run folder: `ecoforest run` holds an exclusive lock on the
// folder's .lock file while it writes there. The lock is the kernel's (flock), so it is
// released however the run ends, kill -9 included; the file keeps the holder's process id
// for the message a second run gets.
#pragma once

#include <filesystem>

namespace eco {

class RunLock {
 public:
  // Creates the folder if needed; InputError naming the folder when another process holds
  // its lock.
  explicit RunLock(const std::filesystem::path& folder);
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();
  // Removes the lock file (and the folder, if the lock made it and it is empty): a run
  // refused before it wrote anything leaves the folder as it found it.
  void abandon();

 private:
  std::filesystem::path folder_;
  bool madeFolder_ = false;
  int descriptor_ = -1;
};

// Whether a run holds the folder's lock now (a run.json saying "running" without one was
// killed).
bool runIsActive(const std::filesystem::path& folder);

}  // namespace eco
