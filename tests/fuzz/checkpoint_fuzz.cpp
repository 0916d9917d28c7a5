// checkpoint.bin (sim/run/checkpoint.hpp). A mutated file almost never keeps a valid
// checksum, which would stop the fuzzer at the first check; so each input is tried twice:
// as it is, and sealed with its own checksum, which takes the bytes to the parser and to
// checkCheckpoint -- the forged lengths and crafted values of a file made on purpose.
#include "fuzz_support.hpp"
#include "sim/run/checkpoint.hpp"
#include "sim/run/checksummed_output.hpp"

namespace {

constexpr std::uint64_t kScenarioHash = 0x5eed;

void readAndCheck(const std::filesystem::path& file) {
  const eco::Grid grid{64, 48, 10.0, 10.0};
  eco::fuzz::expectingInputErrors([&] {
    const eco::Checkpoint checkpoint = eco::readCheckpoint(file, kScenarioHash);
    eco::checkCheckpoint(checkpoint, {grid, 3, 500}, file);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = eco::fuzz::asText(data, size);
  readAndCheck(eco::fuzz::inputFile(bytes, "checkpoint.bin"));
  // Sealed by each hash: the current version's and the older one still read.
  for (const eco::BlockHash hash : {eco::BlockHash::Xxh3, eco::BlockHash::Fnv1a}) {
    std::string sealed(bytes);
    const std::uint64_t checksum = eco::blockChecksum(sealed, hash);
    sealed.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    readAndCheck(eco::fuzz::inputFile(sealed, "sealed.bin"));
  }
  return 0;
}
