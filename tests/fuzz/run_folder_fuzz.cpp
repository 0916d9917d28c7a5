// The files of a run folder that render, view, timelapse, export and validate read back
// (sim/run/run_format.hpp, sim/run/trees_file.hpp): run.json, trees/year_NNNN.csv and .bin,
// and the yield tables of `validate` (sim/run/validation.hpp). The first byte chooses the
// reader. A mutated binary snapshot almost never keeps a valid checksum, so it is also tried
// sealed with its own (as checkpoint_fuzz does), to reach the rows behind the check.
#include "fuzz_support.hpp"
#include "sim/run/checksummed_output.hpp"
#include "sim/run/run_format.hpp"
#include "sim/run/validation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text = eco::fuzz::asText(data + 1, size - 1);
  switch (data[0] % 5) {
    case 0: {
      const auto file = eco::fuzz::inputFile(text, "run.json");
      eco::fuzz::expectingInputErrors([&] { eco::readRunJson(eco::RunPaths{file.parent_path()}); });
      break;
    }
    case 1: {
      const auto file = eco::fuzz::inputFile(text, "year_0010.csv");
      eco::fuzz::expectingInputErrors([&] { eco::readTreesCsv(file); });
      break;
    }
    case 2: {
      const auto file = eco::fuzz::inputFile(text, "yield_table.csv");
      eco::fuzz::expectingInputErrors([&] { eco::readYieldTable(file); });
      break;
    }
    default: {
      std::string bytes(text);
      if (data[0] % 5 == 4) {
        // Sealed by the hash of version 1 (FNV-1a) or of version 2 (XXH3).
        const std::uint64_t checksum = eco::blockChecksum(
            bytes, data[0] % 10 == 4 ? eco::BlockHash::Fnv1a : eco::BlockHash::Xxh3);
        bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
      }
      const auto file = eco::fuzz::inputFile(bytes, "year_0010.bin");
      eco::fuzz::expectingInputErrors([&] { eco::readTreesBinary(file); });
      break;
    }
  }
  return 0;
}
