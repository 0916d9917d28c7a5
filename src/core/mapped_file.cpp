#include "core/mapped_file.hpp"

#include <cstdint>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace eco {

std::optional<MappedFile> MappedFile::open(const std::filesystem::path& file, Reading reading) {
  const int descriptor = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) return std::nullopt;
  struct stat status {};
  if (::fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(descriptor);
    return std::nullopt;
  }
  const auto size = static_cast<std::size_t>(status.st_size);
  void* data = nullptr;
  if (size > 0) {
    // Read whole, populated at once: the reader goes through every byte, and a page fault
    // each on reader threads is slower. In parts, read ahead of the reader.
    const int populate = reading == Reading::Whole ? MAP_POPULATE : 0;
    data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | populate, descriptor, 0);
    if (data == MAP_FAILED)
      data = nullptr;
    else if (reading == Reading::InParts)
      ::madvise(data, size, MADV_SEQUENTIAL);
  }
  ::close(descriptor);  // the mapping stays
  if (size > 0 && data == nullptr) return std::nullopt;
  return MappedFile(static_cast<const char*>(data), size);
}

MappedFile::MappedFile(MappedFile&& other) noexcept : data_(other.data_), size_(other.size_) {
  other.data_ = nullptr;
  other.size_ = 0;
}

void MappedFile::release(std::string_view part) const {
  if (part.empty()) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  // The pages wholly inside the part: a page it shares with the next part is still read.
  const std::uintptr_t begin =
      (reinterpret_cast<std::uintptr_t>(part.data()) + page - 1) / page * page;
  const std::uintptr_t end =
      reinterpret_cast<std::uintptr_t>(part.data() + part.size()) / page * page;
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
}

MappedFile::~MappedFile() {
  if (data_ != nullptr) ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace eco
