// Species files (model/species.hpp): TOML with EcoMod's parameters or an L-system.
#include "fuzz_support.hpp"
#include "model/species.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = eco::fuzz::inputFile(eco::fuzz::asText(data, size), "species.toml");
  eco::fuzz::expectingInputErrors([&] { eco::loadSpecies(file); });
  return 0;
}
