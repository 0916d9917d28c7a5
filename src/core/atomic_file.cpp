#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/error.hpp"

namespace eco {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
constexpr std::string_view kTemporaryMark = ".tmp-";

std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = target;
  temporary +=
      std::string(kTemporaryMark) + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temporary;
}

std::filesystem::path folderOf(const std::filesystem::path& file) {
  return file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
}

}  // namespace

bool isAtomicTemporary(std::string_view fileName) {
  return fileName.find(kTemporaryMark) != std::string_view::npos;
}

bool createOutputFolder(const std::filesystem::path& folder) {
  std::error_code error;
  const bool made = std::filesystem::create_directories(folder, error);
  if (error)
    throw EnvironmentError(folder.string() +
                           ": cannot create the output folder: " + error.message());
  return made;
}

void syncFolder(const std::filesystem::path& folder) {
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) return;
  ::fsync(descriptor);
  ::close(descriptor);
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporaryNameFor(target_)), cleanup_(temporary_) {
  descriptor_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (descriptor_ < 0) {
    const int error = errno;
    cleanup_.release();
    done_ = true;
    if (!std::filesystem::is_directory(folderOf(target_)))
      throw InputError({target_.string(), 0, ""},
                       "cannot write this file: its folder does not exist");
    throw EnvironmentError(target_.string() + ": cannot write this file: " + std::strerror(error));
  }
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      descriptor_(other.descriptor_),
      buffer_(std::move(other.buffer_)),
      cleanup_(std::move(other.cleanup_)),
      done_(other.done_) {
  other.descriptor_ = -1;
  other.done_ = true;
}

AtomicFile::~AtomicFile() {
  if (descriptor_ >= 0) ::close(descriptor_);
  if (done_) return;
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::fail(const char* what, int error) {
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = -1;
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
  cleanup_.release();
  done_ = true;
  throw EnvironmentError(target_.string() + ": " + what + ": " + std::strerror(error) +
                         " (nothing was written under this name)");
}

void AtomicFile::writeOut(std::string_view bytes) {
  if (done_) throw InternalError("AtomicFile written after commit or failure: " + target_.string());
  while (!bytes.empty()) {
    const ssize_t written = ::write(descriptor_, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    // write() returning 0 for a non-empty request means no room: report it as a full disk.
    if (written <= 0) fail("writing failed", written < 0 ? errno : ENOSPC);
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
}

void AtomicFile::write(std::span<const unsigned char> bytes) {
  write(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void AtomicFile::write(std::string_view text) {
  if (buffer_.size() + text.size() > kBufferBytes) {
    writeOut(buffer_);
    buffer_.clear();
  }
  if (text.size() >= kBufferBytes)
    writeOut(text);
  else
    buffer_.append(text);
}

void AtomicFile::flush() {
  writeOut(buffer_);
  buffer_.clear();
  buffer_.shrink_to_fit();
  if (::fsync(descriptor_) != 0 && errno != EINVAL) fail("writing failed", errno);
}

void AtomicFile::commit() {
  flush();
  const int closed = ::close(descriptor_);
  descriptor_ = -1;
  if (closed != 0) fail("writing failed", errno);
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error) fail("cannot rename into place", error.value());
  cleanup_.release();
  done_ = true;
  syncFolder(folderOf(target_));
}

AtomicFile& AtomicFileSet::add(const std::filesystem::path& target) {
  files_.emplace_back(target);
  return files_.back();
}

void AtomicFileSet::commit() {
  for (AtomicFile& file : files_) file.flush();
  for (AtomicFile& file : files_) file.commit();
}

BackgroundCommits::~BackgroundCommits() {
  if (last_.valid()) last_.wait();
}

void BackgroundCommits::commit(AtomicFile file) {
  // A failure already known stops the caller now, not at the end of its work.
  if (last_.valid() && last_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    last_.get();
  last_ =
      std::async(std::launch::async, [before = std::move(last_), file = std::move(file)]() mutable {
        // In order: a file is renamed into place after the one before it. If that one
        // failed, this one's temporary is removed with `file`.
        if (before.valid()) before.get();
        file.commit();
      });
}

void BackgroundCommits::wait() {
  if (last_.valid()) last_.get();
}

}  // namespace eco
