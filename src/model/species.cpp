#include "model/species.hpp"

#include <algorithm>

#include "core/names.hpp"
#include "core/toml_reader.hpp"
#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"
#include "model/lsystem/turtle.hpp"

namespace eco {
namespace {

LeafDistribution parseDistribution(TomlTable& table, std::string_view key) {
  std::string name = table.string(key);
  for (LeafDistribution d :
       {LeafDistribution::Spiral, LeafDistribution::Stacked, LeafDistribution::Staggered,
        LeafDistribution::Bunched, LeafDistribution::Coniferous})
    if (name == toString(d)) return d;
  table.fail(key, "unknown leaf distribution '" + name +
                      "' (expected spiral, stacked, staggered, bunched or coniferous)");
}

glm::vec3 parseColor(TomlTable& table, std::string_view key, glm::vec3 fallback) {
  auto c =
      table.numbers(key, 3, std::vector<double>{fallback.r, fallback.g, fallback.b}, {0.0, 1.0});
  return glm::vec3(c[0], c[1], c[2]);
}

// The ranges are the paper's (section II.A for scalars, II.B for the auxiliary graphs).
LocalGraphs parseGraphs(TomlTable& local) {
  LocalGraphs g;
  g.ksG = local.polyline("ks_g", {0.5, 1.0});
  g.ksW = local.polyline("ks_w", {0.0, 2.0});
  g.alphaG = local.polyline("alpha_g_deg", {0.0, 180.0});
  g.alphaW = local.polyline("alpha_w", {0.0, 2.0});
  g.alphaMG = local.polyline("alpha_m_g_deg", {-180.0, 180.0});
  g.alphaMW = local.polyline("alpha_m_w", {0.0, 2.0});
  g.maxLenG = local.polyline("max_length_g", {0.0, 10.0});
  g.maxLenW = local.polyline("max_length_w", {0.0, 2.0});
  g.klG = local.polyline("kl_g", {0.0, 10.0});
  g.klW = local.polyline("kl_w", {0.0, 2.0});
  g.minLenG = local.polyline("min_length_g", {0.0, 10.0});
  g.minLenW = local.polyline("min_length_w", {0.0, 2.0});
  local.finish();
  return g;
}

// EcoMod's wind keys, shared by [strand] and [lsystem]; every one is optional.
WindParams parseWind(TomlTable& table) {
  WindParams p;
  p.directed_wg = table.number("wind_directed_wg", p.directed_wg, {0.0, 10.0});
  p.undirected_ws = table.number("wind_undirected_ws", p.undirected_ws, {0.0, 10.0});
  auto w = table.numbers("wind_direction", 3,
                         std::vector<double>{p.direction.x, p.direction.y, p.direction.z},
                         Range{-1000.0, 1000.0});
  p.direction = glm::dvec3(w[0], w[1], w[2]);
  p.flexibility = table.number("flexibility_kf", p.flexibility, {0.0, 1.0});
  return p;
}

void parseStrand(TomlTable& root, StrandParams& p, WindParams& wind) {
  std::optional<TomlTable> strand = root.table("strand");
  if (!strand) root.fail("strand", "missing required table [strand]");

  // The paper's slider stops at 5000, yet its own pine has S = 6000: the slider bound is
  // not a validity limit. 100000 keeps a typo from exhausting memory.
  p.strands = static_cast<int>(strand->integer("strands", {}, {1, 100000}));
  p.trunkLength_m = strand->number("trunk_length_m", {}, {0.0, 10.0});
  p.kd = strand->number("kd", {}, {0.0, 0.05});
  p.phyllotaxis_deg = strand->number("phyllotaxis_deg", {}, {0.0, 360.0});
  p.kc = strand->number("kc", {}, {0.0, 1.0});
  p.leafSize_m = strand->number("leaf_size_m", {}, {0.0, 0.3});
  p.leafDensity = strand->number("leaf_density", {}, {0.0, 30.0});
  p.leafDistribution = parseDistribution(*strand, "leaf_distribution");
  wind = parseWind(*strand);
  p.lod = static_cast<int>(strand->integer("lod", 0, {0, 2}));
  std::optional<TomlTable> local = strand->table("local");
  if (!local) strand->fail("local", "missing required table [strand.local]");
  p.graphs = parseGraphs(*local);
  strand->finish();
}

// Also reads EcoMod's wind parameters, which bend L-system trees as they do strand trees.
LSystemTree parseLSystemTree(TomlTable& table, const std::filesystem::path& speciesFile,
                             WindParams& wind) {
  LSystemTree tree;
  tree.grammarFile = speciesFile.parent_path() / table.string("file");
  if (!std::filesystem::is_regular_file(tree.grammarFile))
    table.fail("file", "grammar file '" + tree.grammarFile.string() + "' not found");
  auto grammar = std::make_shared<LSystem>(loadLSystem(tree.grammarFile));
  tree.iterations =
      static_cast<int>(table.integer("iterations", grammar->iterations, {1, kMaxIterations}));
  tree.unit_m = table.number("unit_m", grammar->turtle.unit_m, {1e-6, 1e6});
  wind = parseWind(table);
  // A species must be a plant: its mature tree has to draw wood.
  DeriveOptions mature;
  mature.iterations = tree.iterations;
  if (interpretTree(*grammar, derive(*grammar, mature)).segments.empty())
    table.fail("file", "the grammar draws no wood (no F) after " + std::to_string(tree.iterations) +
                           " steps: it cannot grow a tree");
  tree.grammar = std::move(grammar);
  table.finish();
  return tree;
}

}  // namespace

const char* toString(LeafDistribution distribution) {
  switch (distribution) {
    case LeafDistribution::Spiral:
      return "spiral";
    case LeafDistribution::Stacked:
      return "stacked";
    case LeafDistribution::Staggered:
      return "staggered";
    case LeafDistribution::Bunched:
      return "bunched";
    case LeafDistribution::Coniferous:
      return "coniferous";
  }
  return "?";
}

bool Species::isCalled(std::string_view called) const {
  return sameNameIgnoringCase(name, called) ||
         std::any_of(commonNames.begin(), commonNames.end(), [&](const std::string& common) {
           return sameNameIgnoringCase(common, called);
         });
}

Species loadSpecies(const std::filesystem::path& file) {
  TomlDocument document = TomlDocument::load(file);
  TomlTable root = document.root();
  Species species;
  species.file = file;
  species.name = root.string("name");
  species.latinName = root.string("latin_name", "");
  species.commonNames = root.stringList("common_names", {});
  // A species' name becomes part of file names (maps/suitability_NAME) and a field of the
  // run's CSV files: it must be a plain word there.
  if (const std::string why = whyNotAPlainName(species.name); !why.empty())
    root.fail("name", "'" + species.name + "' cannot name a species: " + why);

  const std::string generator = root.string("generator", "strand");
  if (generator == "lsystem") {
    species.generator = TreeGenerator::LSystem;
    std::optional<TomlTable> table = root.table("lsystem");
    if (!table) root.fail("lsystem", "generator = \"lsystem\" needs a table [lsystem]");
    species.lsystem = parseLSystemTree(*table, file, species.wind);
  } else if (generator != "strand") {
    root.fail("generator", "unknown generator '" + generator + "' (expected strand or lsystem)");
  } else {
    parseStrand(root, species.strand, species.wind);
  }

  if (std::optional<TomlTable> variation = root.table("variation")) {
    Variation& v = species.variation;
    v.branchAngle = variation->number("branch_angle", v.branchAngle, {0.0, 0.5});
    v.phyllotaxis_deg = variation->number("phyllotaxis_deg", v.phyllotaxis_deg, {0.0, 90.0});
    v.length = variation->number("length", v.length, {0.0, 0.5});
    variation->finish();
  }
  if (std::optional<TomlTable> look = root.table("appearance")) {
    Appearance& a = species.appearance;
    a.barkColor = parseColor(*look, "bark_color", a.barkColor);
    a.leafColor = parseColor(*look, "leaf_color", a.leafColor);
    std::string shape = look->string("leaf_shape", "broadleaf");
    if (shape == "broadleaf")
      a.leafShape = LeafShape::Broadleaf;
    else if (shape == "needle_tuft")
      a.leafShape = LeafShape::NeedleTuft;
    else
      look->fail("leaf_shape",
                 "unknown leaf shape '" + shape + "' (expected broadleaf or needle_tuft)");
    a.barkRoughness = look->number("bark_roughness", a.barkRoughness, {0.0, 1.0});
    look->finish();
  }
  root.leave("ecology");  // the simulation's (sim/species_ecology.hpp)
  root.finish();
  return species;
}

}  // namespace eco
