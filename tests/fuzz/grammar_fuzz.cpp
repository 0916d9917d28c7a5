// Green's RL-system grammar files (model/lsystem/parser.hpp): parsed from text, as
// `ecoforest lsystem` and L-system species read them.
#include "fuzz_support.hpp"
#include "model/lsystem/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  eco::fuzz::expectingInputErrors(
      [&] { eco::parseLSystem(eco::fuzz::asText(data, size), "grammar.lsys"); });
  return 0;
}
