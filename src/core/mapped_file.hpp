// A file's bytes mapped into memory, read-only, for the large files ecoforest reads back
// whole (tree snapshots, checkpoints): no buffer of the file's size is allocated, zeroed and
// copied into, which took 1.3 s of reading a 263 MB snapshot where the mapping takes 0.14 s.
// ecoforest replaces its files by renaming new ones over them, so a mapped file keeps its
// bytes while it is read; a file truncated in place meanwhile would end the process.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

namespace eco {

class MappedFile {
 public:
  // How a reader goes through the bytes: all of them held at once (the mapping filled in
  // as it is made), or in order, a part at a time, each part released when it is done, so
  // the process never holds more of the file than the parts it reads (a landscape's
  // snapshot of 4 GB, of which a stand table keeps a tenth).
  enum class Reading { Whole, InParts };
  // Nothing when the file cannot be opened or is not a regular file.
  static std::optional<MappedFile> open(const std::filesystem::path& file,
                                        Reading reading = Reading::Whole);
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&&) = delete;
  MappedFile(const MappedFile&) = delete;
  ~MappedFile();

  std::string_view bytes() const { return {data_, size_}; }
  // Done with `part` (bytes of bytes()): the whole pages it spans leave the process's
  // memory; read again, they come back from the file.
  void release(std::string_view part) const;

 private:
  MappedFile(const char* data, std::size_t size) : data_(data), size_(size) {}
  const char* data_ = nullptr;  // null for an empty file
  std::size_t size_ = 0;
};

}  // namespace eco
