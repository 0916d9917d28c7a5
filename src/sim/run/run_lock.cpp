#include "sim/run/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace eco {
namespace {

std::filesystem::path lockFile(const std::filesystem::path& folder) {
  return folder / ".lock";
}

}  // namespace

RunLock::RunLock(const std::filesystem::path& folder) : folder_(folder) {
  madeFolder_ = createOutputFolder(folder);
  descriptor_ = ::open(lockFile(folder).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (descriptor_ < 0)
    throw EnvironmentError(lockFile(folder).string() +
                           ": cannot create the run folder's lock: " + std::strerror(errno));
  if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
    char holder[32] = {};
    const ssize_t length = ::pread(descriptor_, holder, sizeof holder - 1, 0);
    ::close(descriptor_);
    descriptor_ = -1;
    const std::string pid = length > 0 ? std::string(holder, static_cast<std::size_t>(length)) : "";
    throw InputError({folder.string(), 0, "--out"},
                     "another ecoforest run" + (pid.empty() ? "" : " (process " + pid + ")") +
                         " is writing into this folder; wait for it to finish, stop it, or run "
                         "into another folder with --out");
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(descriptor_, 0) == 0 && ::pwrite(descriptor_, pid.data(), pid.size(), 0) < 0) {
    // The process id only improves a message: failing to record it is not an error.
  }
}

RunLock::~RunLock() {
  if (descriptor_ >= 0) ::close(descriptor_);  // closing releases the lock
}

void RunLock::abandon() {
  std::error_code ignored;
  std::filesystem::remove(lockFile(folder_), ignored);
  if (madeFolder_ && std::filesystem::is_empty(folder_, ignored))
    std::filesystem::remove(folder_, ignored);
}

bool runIsActive(const std::filesystem::path& folder) {
  const int descriptor = ::open(lockFile(folder).c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) return false;
  const bool held = ::flock(descriptor, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(descriptor);
  return held;
}

}  // namespace eco
