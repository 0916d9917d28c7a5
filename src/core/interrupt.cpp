#include "core/interrupt.hpp"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <csignal>
#include <cstddef>
#include <cstring>

namespace eco {
namespace {

enum SlotState : int { kFree = 0, kWriting = 1, kReady = 2 };

// Fixed storage the signal handler can read without allocating or locking.
struct Slot {
  std::atomic<int> state{kFree};
  InterruptCleanup::Kind kind = InterruptCleanup::Kind::file;
  char path[4096] = {};
};
Slot slots[kInterruptSlots];
std::atomic<std::atomic<bool>*> gracefulFlag{nullptr};

// Removes the files in a folder and then the folder, with system calls that are safe in a
// signal handler (no opendir, which allocates). Repeats while a pass removed something, as
// removing entries while listing them may skip some.
void removeFolder(const char* path) {
  for (bool removed = true; removed;) {
    removed = false;
    const int folder = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder < 0) return;
    alignas(8) char buffer[4096];
    for (long bytes; (bytes = ::syscall(SYS_getdents64, folder, buffer, sizeof buffer)) > 0;)
      for (long offset = 0; offset < bytes;) {
        // struct linux_dirent64: inode (8), offset (8), record length (2), type (1), name.
        unsigned short length = 0;
        std::memcpy(&length, buffer + offset + 16, sizeof length);
        const char* name = buffer + offset + 19;
        if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0 &&
            ::unlinkat(folder, name, 0) == 0)
          removed = true;
        offset += length;
      }
    ::close(folder);
  }
  ::rmdir(path);
}

void removeRegistered() {
  for (Slot& slot : slots) {
    if (slot.state.load() != kReady) continue;
    if (slot.kind == InterruptCleanup::Kind::folder)
      removeFolder(slot.path);
    else
      ::unlink(slot.path);
  }
}

extern "C" void onInterrupt(int signal) {
  std::atomic<bool>* flag = gracefulFlag.load();
  if (flag && !flag->load()) {
    flag->store(true);
    return;
  }
  removeRegistered();
  ::_exit(128 + signal);  // as shells report a process killed by the signal
}

}  // namespace

void installInterruptCleanup() {
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

InterruptCleanup::InterruptCleanup(const std::filesystem::path& path, Kind kind) {
  const std::string absolute = std::filesystem::absolute(path).string();
  if (absolute.size() >= sizeof(Slot::path)) return;
  for (int i = 0; i < kInterruptSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kWriting)) continue;
    slots[i].kind = kind;
    std::memcpy(slots[i].path, absolute.c_str(), absolute.size() + 1);
    slots[i].state.store(kReady);
    slot_ = i;
    return;
  }
}

InterruptCleanup::InterruptCleanup(InterruptCleanup&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

InterruptCleanup::~InterruptCleanup() {
  release();
}

void InterruptCleanup::release() {
  if (slot_ >= 0) slots[slot_].state.store(kFree);
  slot_ = -1;
}

GracefulStop::GracefulStop(std::atomic<bool>& flag) {
  gracefulFlag.store(&flag);
}

GracefulStop::~GracefulStop() {
  gracefulFlag.store(nullptr);
}

}  // namespace eco
