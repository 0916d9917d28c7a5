// The files of a run folder that render, view, timelapse, export and validate read back
// (sim/run/run_format.hpp): run.json and trees/year_NNNN.csv, and the yield tables of
// `validate` (sim/run/validation.hpp). The first byte chooses the reader.
#include "fuzz_support.hpp"
#include "sim/run/run_format.hpp"
#include "sim/run/validation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text = eco::fuzz::asText(data + 1, size - 1);
  switch (data[0] % 3) {
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
    default: {
      const auto file = eco::fuzz::inputFile(text, "yield_table.csv");
      eco::fuzz::expectingInputErrors([&] { eco::readYieldTable(file); });
      break;
    }
  }
  return 0;
}
