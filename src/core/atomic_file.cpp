#include "core/atomic_file.hpp"

#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace eco {
namespace {

std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = target;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temporary;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporaryNameFor(target_)) {
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    const std::filesystem::path folder =
        target_.parent_path().empty() ? std::filesystem::path(".") : target_.parent_path();
    if (!std::filesystem::is_directory(folder))
      throw InputError({target_.string(), 0, ""},
                       "cannot write this file: its folder does not exist");
    throw EnvironmentError(target_.string() + ": cannot write this file: " + std::strerror(errno));
  }
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      stream_(std::move(other.stream_)),
      done_(other.done_) {
  other.done_ = true;
}

AtomicFile::~AtomicFile() {
  if (done_) return;
  stream_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::write(std::span<const unsigned char> bytes) {
  stream_.write(reinterpret_cast<const char*>(bytes.data()),
                static_cast<std::streamsize>(bytes.size()));
}

void AtomicFile::write(std::string_view text) {
  stream_.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void AtomicFile::commit() {
  stream_.flush();
  bool ok = static_cast<bool>(stream_);
  const int writeError = errno;
  stream_.close();
  ok = ok && static_cast<bool>(stream_);
  if (!ok)
    throw EnvironmentError(target_.string() + ": writing failed: " + std::strerror(writeError));
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error)
    throw EnvironmentError(target_.string() + ": cannot rename into place: " + error.message());
  done_ = true;
}

AtomicFile& AtomicFileSet::add(const std::filesystem::path& target) {
  files_.emplace_back(target);
  return files_.back();
}

void AtomicFileSet::commit() {
  for (AtomicFile& file : files_) {
    file.stream().flush();
    if (!file.stream())
      throw EnvironmentError(file.target().string() + ": writing failed: " + std::strerror(errno));
  }
  for (AtomicFile& file : files_) file.commit();
}

}  // namespace eco
