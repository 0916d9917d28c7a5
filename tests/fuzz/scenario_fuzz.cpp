// Scenario files (sim/scenario.hpp).
#include "fuzz_support.hpp"
#include "sim/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = eco::fuzz::inputFile(eco::fuzz::asText(data, size), "scenario.toml");
  eco::fuzz::expectingInputErrors([&] { eco::loadScenario(file); });
  return 0;
}
