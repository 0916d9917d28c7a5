#include "model/species.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/names.hpp"
#include "core/toml_reader.hpp"
#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"
#include "model/lsystem/turtle.hpp"
#include "model/species_schema.hpp"

namespace eco {
namespace {

LeafDistribution parseDistribution(TomlTable& table, std::string_view key) {
  const std::string name = table.string(key);
  if (std::optional<LeafDistribution> d = leafDistributionNamed(name)) return *d;
  table.fail(key, "unknown leaf distribution '" + name +
                      "' (expected spiral, stacked, staggered, bunched or coniferous)");
}

glm::vec3 parseColor(TomlTable& table, std::string_view key, glm::vec3 fallback) {
  auto c =
      table.numbers(key, 3, std::vector<double>{fallback.r, fallback.g, fallback.b}, {0.0, 1.0});
  return glm::vec3(c[0], c[1], c[2]);
}

// The bounds are the paper's (model/species_schema.hpp).
LocalGraphs parseGraphs(TomlTable& local) {
  LocalGraphs graphs;
  for (const LocalGraphInfo& info : localGraphs())
    graphOf(graphs, info.graph) = local.polyline(info.key, info.values);
  local.finish();
  return graphs;
}

// One global parameter; required without a fallback.
void parseGlobal(TomlTable& table, GlobalParameter parameter, Species& species,
                 std::optional<double> fallback = {}) {
  const GlobalParameterInfo& info = infoOf(parameter);
  ECO_ASSERT(!(info.integer && fallback), info.key << ": integers here are required keys");
  const double value = info.integer ? static_cast<double>(table.integer(info.key, {}, info.valid))
                                    : table.number(info.key, fallback, info.valid);
  setValue(species, parameter, value);
}

// EcoMod's wind keys, shared by [strand] and [lsystem]; every one is optional.
void parseWind(TomlTable& table, Species& species) {
  const WindParams defaults;
  parseGlobal(table, GlobalParameter::WindDirected, species, defaults.directed_wg);
  parseGlobal(table, GlobalParameter::WindUndirected, species, defaults.undirected_ws);
  auto w = table.numbers(
      "wind_direction", 3,
      std::vector<double>{defaults.direction.x, defaults.direction.y, defaults.direction.z},
      Range{-1000.0, 1000.0});
  species.wind.direction = glm::dvec3(w[0], w[1], w[2]);
  parseGlobal(table, GlobalParameter::Flexibility, species, defaults.flexibility);
}

void parseStrand(TomlTable& root, Species& species) {
  std::optional<TomlTable> strand = root.table("strand");
  if (!strand) root.fail("strand", "missing required table [strand]");
  for (GlobalParameter parameter :
       {GlobalParameter::Strands, GlobalParameter::TrunkLength, GlobalParameter::Kd,
        GlobalParameter::Phyllotaxis, GlobalParameter::Kc, GlobalParameter::LeafSize,
        GlobalParameter::LeafDensity})
    parseGlobal(*strand, parameter, species);
  StrandParams& p = species.strand;
  p.leafDistribution = parseDistribution(*strand, "leaf_distribution");
  parseWind(*strand, species);
  p.lod = static_cast<int>(strand->integer("lod", 0, {0, 2}));
  std::optional<TomlTable> local = strand->table("local");
  if (!local) strand->fail("local", "missing required table [strand.local]");
  p.graphs = parseGraphs(*local);
  strand->finish();
}

// Also reads EcoMod's wind parameters, which bend L-system trees as they do strand trees.
LSystemTree parseLSystemTree(TomlTable& table, const std::filesystem::path& speciesFile,
                             Species& species) {
  LSystemTree tree;
  tree.grammarFile = speciesFile.parent_path() / table.string("file");
  if (!std::filesystem::is_regular_file(tree.grammarFile))
    table.fail("file", "grammar file '" + tree.grammarFile.string() + "' not found");
  auto grammar = std::make_shared<LSystem>(loadLSystem(tree.grammarFile));
  tree.iterations =
      static_cast<int>(table.integer("iterations", grammar->iterations, {1, kMaxIterations}));
  tree.unit_m = table.number("unit_m", grammar->turtle.unit_m, {1e-6, 1e6});
  parseWind(table, species);
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

std::optional<LeafDistribution> leafDistributionNamed(std::string_view name) {
  for (LeafDistribution d : kLeafDistributions)
    if (name == toString(d)) return d;
  return std::nullopt;
}

const char* toString(LeafShape shape) {
  return shape == LeafShape::NeedleTuft ? "needle_tuft" : "broadleaf";
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
    species.lsystem = parseLSystemTree(*table, file, species);
  } else if (generator != "strand") {
    root.fail("generator", "unknown generator '" + generator + "' (expected strand or lsystem)");
  } else {
    parseStrand(root, species);
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
    const std::string shape = look->string("leaf_shape", toString(LeafShape::Broadleaf));
    if (shape == toString(LeafShape::Broadleaf))
      a.leafShape = LeafShape::Broadleaf;
    else if (shape == toString(LeafShape::NeedleTuft))
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
