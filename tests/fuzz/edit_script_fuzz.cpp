// Designer edit files (model/design/edit_script.hpp) applied to the paper's beech. Beyond
// not crashing, whatever the edits, the species the designer saves must read back: every
// edit clamps to the bounds the species reader checks, so a saved file is never refused.
#include <cstdlib>

#include "fuzz_support.hpp"
#include "model/design/edit_script.hpp"
#include "model/species_writer.hpp"

namespace {

// The beech's [strand] as the paper gives it (section III.A).
constexpr const char* kBeech = R"(name = "beech"
[strand]
strands = 1000
trunk_length_m = 5.0
kd = 0.01
phyllotaxis_deg = 85.0
kc = 0.3
leaf_size_m = 0.2862
leaf_density = 5.0
leaf_distribution = "spiral"
wind_directed_wg = 1.5
[strand.local]
ks_g = [[0, 0.75], [15, 0.9]]
ks_w = [[0, 1], [50, 1]]
alpha_g_deg = [[0, 45], [15, 45]]
alpha_w = [[0, 1], [50, 1]]
min_length_g = [[0, 1], [7.5, 0.45], [15, 1]]
min_length_w = [[0, 1], [50, 1]]
max_length_g = [[0, 1], [15, 1]]
max_length_w = [[0, 1], [50, 1]]
kl_g = [[0, 1], [15, 1]]
kl_w = [[0, 1], [50, 1]]
alpha_m_g_deg = [[0, 0], [15, 0]]
alpha_m_w = [[0, 1], [50, 1]]
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const eco::Species beech = eco::loadSpecies(eco::fuzz::inputFile(kBeech, "beech.toml"));
  const auto file = eco::fuzz::inputFile(eco::fuzz::asText(data, size), "edits.toml");
  eco::DesignSession session(beech);
  bool applied = false;
  eco::fuzz::expectingInputErrors([&] {
    eco::applyEditScript(eco::loadEditScript(file), session);
    applied = true;
  });
  if (!applied) return 0;
  const auto saved = eco::fuzz::inputFile(eco::speciesToml(session.species(), ""), "saved.toml");
  try {
    eco::loadSpecies(saved);
  } catch (const eco::InputError&) {
    std::abort();  // the designer saved a species its own reader refuses
  }
  return 0;
}
