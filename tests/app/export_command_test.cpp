// Runs `ecoforest export` as a user would, and opens what it writes in the clients users
// have: the Khronos validator, Blender, assimp and three.js (each skipped with a message
// where it is not installed; scripts/test installs them).
#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app_support.hpp"
#include "core/frames.hpp"
#include "gltf_files.hpp"
#include "sim/run/run_format.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;
using eco::test::shortDefaultRun;

const std::filesystem::path kTools = std::filesystem::path(ECOFOREST_SOURCE_DIR) / "tools";
const std::filesystem::path kNode = kTools / "gltf-validator";

bool installed(const std::string& program) {
  return eco::test::runCommand("command -v " + program).exitCode == 0;
}

// The snapshot a test exports, and the year-20 export of it in one instancing mode.
const eco::TreeSnapshot& snapshot() {
  static const eco::TreeSnapshot s = eco::readTrees(shortDefaultRun() / "trees" / "year_0020.csv");
  return s;
}
const std::filesystem::path& exported(const std::string& instancing) {
  static std::map<std::string, std::filesystem::path> files;
  auto [it, added] = files.try_emplace(instancing);
  if (added) {
    it->second = eco::test::freshDirectory("app_export_" + instancing) / "forest.glb";
    CommandResult r = ecoforest("export " + shortDefaultRun().string() + " --instancing " +
                                instancing + " --out " + it->second.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const std::string mode = instancing == "gpu" ? "GPU instances" : "nodes";
    EXPECT_NE(r.output.find(fmt::format("year 20, {} trees as {}", snapshot().trees.size(), mode)),
              std::string::npos)
        << r.output;
  }
  return it->second;
}

// What an exported tree says about itself, keyed by id.
struct ExportedTree {
  std::string species;
  int age = 0;
  float height_m = 0, dbh_m = 0, vigor = 0;
  glm::vec3 position{0.0f};
};

template <typename T>
T valueAt(const tinygltf::Model& model, const tinygltf::Value& accessor, std::size_t i) {
  const tinygltf::Accessor& a = model.accessors[accessor.GetNumberAsInt()];
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  return reinterpret_cast<const T*>(model.buffers[view.buffer].data.data() + view.byteOffset +
                                    a.byteOffset)[i];
}

std::map<std::uint64_t, ExportedTree> exportedTrees(const tinygltf::Model& model) {
  std::map<std::uint64_t, ExportedTree> trees;
  const tinygltf::Value& names = model.scenes[0].extras.Get("species");
  for (const tinygltf::Node& node : model.nodes) {
    if (node.extras.Has("id")) {  // --instancing nodes
      ExportedTree& t =
          trees[static_cast<std::uint64_t>(node.extras.Get("id").GetNumberAsDouble())];
      t.species = node.extras.Get("species").Get<std::string>();
      t.age = node.extras.Get("age").GetNumberAsInt();
      t.height_m = static_cast<float>(node.extras.Get("height_m").GetNumberAsDouble());
      t.dbh_m = static_cast<float>(node.extras.Get("dbh_m").GetNumberAsDouble());
      t.vigor = static_cast<float>(node.extras.Get("vigor").GetNumberAsDouble());
      t.position = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
    }
    if (!node.extensions.count("EXT_mesh_gpu_instancing")) continue;
    const tinygltf::Value& a = node.extensions.at("EXT_mesh_gpu_instancing").Get("attributes");
    const std::size_t count = model.accessors[a.Get("_ID").GetNumberAsInt()].count;
    for (std::size_t i = 0; i < count; ++i) {
      ExportedTree& t = trees[valueAt<std::uint32_t>(model, a.Get("_ID"), i)];
      t.species = names.Get(valueAt<std::uint16_t>(model, a.Get("_SPECIES"), i)).Get<std::string>();
      t.age = static_cast<int>(valueAt<float>(model, a.Get("_AGE"), i));
      t.height_m = valueAt<float>(model, a.Get("_HEIGHT"), i);
      t.dbh_m = valueAt<float>(model, a.Get("_DBH"), i);
      t.vigor = valueAt<float>(model, a.Get("_VIGOR"), i);
      t.position = valueAt<glm::vec3>(model, a.Get("TRANSLATION"), i);
    }
  }
  return trees;
}

std::set<std::uint64_t> csvIds() {
  std::set<std::uint64_t> ids;
  for (const eco::TreeRow& row : snapshot().trees) ids.insert(row.id);
  return ids;
}

TEST(ExportCommand, EveryTreeCarriesItsCsvRowInBothInstancingModes) {
  for (const char* instancing : {"nodes", "gpu"}) {
    SCOPED_TRACE(instancing);
    const tinygltf::Model model = eco::test::loadGltf(exported(instancing));
    const std::map<std::uint64_t, ExportedTree> trees = exportedTrees(model);
    ASSERT_EQ(trees.size(), snapshot().trees.size());
    const tinygltf::Accessor& terrain =
        model.accessors[model.meshes[model.nodes[0].mesh].primitives[0].attributes.at("POSITION")];
    for (const eco::TreeRow& row : snapshot().trees) {
      ASSERT_TRUE(trees.count(row.id)) << row.id;
      const ExportedTree& t = trees.at(row.id);
      EXPECT_EQ(t.species, snapshot().speciesNames[row.species]);
      EXPECT_EQ(t.age, row.age_years);
      EXPECT_EQ(t.height_m, row.height_m);
      EXPECT_EQ(t.dbh_m, row.dbh_m);
      EXPECT_EQ(t.vigor, row.vigor);
      const glm::vec3 base = eco::worldFromMap(row.east_m, row.north_m, row.ground_m);
      EXPECT_LT(glm::distance(t.position, base), 1e-3f) << row.id;
      // On the terrain, not beyond its edge.
      EXPECT_GE(t.position.x, terrain.minValues[0]) << row.id;
      EXPECT_LE(t.position.x, terrain.maxValues[0]) << row.id;
      EXPECT_GE(t.position.z, terrain.minValues[2]) << row.id;
      EXPECT_LE(t.position.z, terrain.maxValues[2]) << row.id;
    }
  }
}

TEST(ExportCommand, MinHeightLeavesOutTheSmallerPlants) {
  const auto file = eco::test::freshDirectory("app_export_min_height") / "tall.glb";
  CommandResult r =
      ecoforest("export " + shortDefaultRun().string() + " --min-height 2 --out " + file.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::set<std::uint64_t> tall;
  for (const eco::TreeRow& row : snapshot().trees)
    if (row.height_m >= 2.0f) tall.insert(row.id);
  ASSERT_GT(tall.size(), 0u);
  ASSERT_LT(tall.size(), snapshot().trees.size());
  std::set<std::uint64_t> exportedIds;
  for (const auto& [id, tree] : exportedTrees(eco::test::loadGltf(file))) exportedIds.insert(id);
  EXPECT_EQ(exportedIds, tall);
}

TEST(ExportCommand, BothModesAndTextGltfPassTheKhronosValidator) {
  if (!std::filesystem::exists(kNode / "node_modules" / "gltf-validator"))
    GTEST_SKIP() << "the glTF validator is not installed (scripts/setup installs it)";
  const auto text = eco::test::freshDirectory("app_export_text") / "forest.gltf";
  CommandResult r = ecoforest("export " + shortDefaultRun().string() + " --out " + text.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto wind = text.parent_path() / "wind.glb";
  r = ecoforest("export " + shortDefaultRun().string() + " --wind --min-height 2 --out " +
                wind.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto billboards = text.parent_path() / "billboards.glb";
  r = ecoforest("export " + shortDefaultRun().string() +
                " --instancing gpu --lod all --billboards --out " + billboards.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const std::filesystem::path& file :
       {exported("nodes"), exported("gpu"), text, wind, billboards}) {
    CommandResult validated =
        eco::test::runCommand("node " + (kNode / "validate.mjs").string() + " " + file.string());
    EXPECT_EQ(validated.exitCode, 0) << file << validated.output;
    EXPECT_NE(validated.output.find("\"errors\":0"), std::string::npos) << validated.output;
  }
}

// Blender 3.4 (Debian 12's) imports the default export with one object per living tree,
// where the CSV says it stands (Blender's frame is z up: east, north, altitude), with its
// row as custom properties and its species' materials.
TEST(ExportCommand, BlenderImportsOneObjectPerTreeWithItsRowAndMaterials) {
  if (!installed("blender")) GTEST_SKIP() << "blender is not installed (scripts/test installs it)";
  const std::string script = (std::filesystem::path(ECOFOREST_SOURCE_DIR) / "tests" / "app" /
                              "tools" / "blender_import.py")
                                 .string();
  CommandResult r = eco::test::runCommand("blender -b --factory-startup --python " + script +
                                          " -- " + exported("nodes").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::size_t at = r.output.find("ECOFOREST_IMPORT ");
  ASSERT_NE(at, std::string::npos) << r.output;
  const std::size_t begin = at + std::string("ECOFOREST_IMPORT ").size();
  const nlohmann::json report =
      nlohmann::json::parse(r.output.substr(begin, r.output.find('\n', begin) - begin));
  std::map<std::uint64_t, const eco::TreeRow*> rows;
  for (const eco::TreeRow& row : snapshot().trees) rows[row.id] = &row;
  ASSERT_EQ(report["trees"].size(), rows.size());
  EXPECT_EQ(report["objects"].get<std::size_t>(), rows.size() + 1);  // and the terrain
  for (const nlohmann::json& tree : report["trees"]) {
    const eco::TreeRow& row = *rows.at(tree["id"].get<std::uint64_t>());
    const std::string species = snapshot().speciesNames[row.species];
    EXPECT_EQ(tree["species"], species);
    EXPECT_EQ(tree["age"].get<int>(), row.age_years);
    EXPECT_NEAR(tree["height_m"].get<double>(), row.height_m, 1e-6);
    EXPECT_NEAR(tree["location"][0].get<double>(), row.east_m, 1e-3);
    EXPECT_NEAR(tree["location"][1].get<double>(), row.north_m, 1e-3);
    EXPECT_NEAR(tree["location"][2].get<double>(), row.ground_m, 1e-3);
    ASSERT_FALSE(tree["materials"].empty());
    for (const nlohmann::json& material : tree["materials"])
      EXPECT_EQ(material.get<std::string>().rfind(species + "_", 0), 0u) << material;
  }
}

// assimp, and every conversion through it (FBX and the rest), keeps one mesh instance per
// tree of the default export.
TEST(ExportCommand, AssimpCountsOneMeshInstancePerTree) {
  if (!installed("assimp")) GTEST_SKIP() << "assimp is not installed (scripts/test installs it)";
  CommandResult r = eco::test::runCommand("assimp info " + exported("nodes").string() + " -v");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::size_t instances = 0, terrain = 0;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(" (mesh ") == std::string::npos) continue;
    (line.find("terrain") != std::string::npos ? terrain : instances) += 1;
  }
  EXPECT_EQ(terrain, 1u);
  EXPECT_EQ(instances, snapshot().trees.size());
}

// three.js's GLTFLoader reads the GPU instances with their ids.
TEST(ExportCommand, ThreeJsCountsTheGpuInstances) {
  if (!std::filesystem::exists(kNode / "node_modules" / "three"))
    GTEST_SKIP() << "three.js is not installed (scripts/setup installs it)";
  CommandResult r = eco::test::runCommand("node " + (kNode / "count_instances.mjs").string() + " " +
                                          exported("gpu").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json report = nlohmann::json::parse(r.output);
  EXPECT_EQ(report["instances"].get<std::size_t>(), snapshot().trees.size());
  EXPECT_EQ(report["meshes"].get<int>(), 1);  // the terrain
  EXPECT_EQ(report["ids"].get<std::set<std::uint64_t>>(), csvIds());
}

TEST(ExportCommand, AFullDiskOrAReadOnlyFolderIsAClearErrorAndLeavesNothing) {
  const std::string run = shortDefaultRun().string();
  for (const char* file : {"forest.glb", "forest.gltf", "trees.geojson", "trees.csv"}) {
    const std::string out = " --out \"$SPACE/" + std::string(file) + "\"";
    eco::test::expectFullAndReadOnlyDisksFailCleanly("export " + run + out, 8,
                                                     "No space left on device");
  }
}

TEST(ExportCommand, CtrlCLeavesNothingPartial) {
  const auto dir = eco::test::freshDirectory("app_export_interrupt");
  for (const char* after : {"0.2", "0.6", "1.2"}) {
    CommandResult r = eco::test::interruptWhen(
        "export " + shortDefaultRun().string() + " --lod 0 --out " + (dir / "f.gltf").string(),
        std::string("sleep ") + after);
    EXPECT_TRUE(r.exitCode == 130 || r.exitCode == 0) << after << ": " << r.output;
    // A .gltf comes with its .bin: both or neither, and no temporary. A Ctrl-C that comes
    // after both were renamed into place, as the process exits, leaves them there.
    const std::size_t entries = eco::test::entriesIn(dir);
    EXPECT_TRUE(entries == 2u || (entries == 0u && r.exitCode == 130)) << after << ": " << entries;
    std::filesystem::remove(dir / "f.gltf");
    std::filesystem::remove(dir / "f.bin");
  }
}

// The trees of a run belong to its scenario as it was: after an edit, export refuses.
TEST(ExportCommand, AnEditedScenarioUnderARunIsRefused) {
  const auto dir = eco::test::freshDirectory("app_export_edited");
  const std::string scenario =
      "name = \"edited\"\nseed = 3\n[terrain]\ncell_size_m = 10.0\n[terrain.generate]\n"
      "size = 17\nrelief_m = 20.0\n[simulation]\nyears = 2\n[[species]]\nfile = \"" +
      (std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / "beech.toml").string() +
      "\"\nseed_rain_per_ha_per_year = 50.0\n";
  eco::test::writeFile(dir / "s.toml", scenario);
  ASSERT_EQ(
      ecoforest("run " + (dir / "s.toml").string() + " --out " + (dir / "run").string()).exitCode,
      0);
  ASSERT_EQ(
      ecoforest("export " + (dir / "run").string() + " --out " + (dir / "a.glb").string()).exitCode,
      0);
  eco::test::writeFile(dir / "s.toml",
                       std::string(scenario).replace(scenario.find("20.0"), 4, "80.0"));
  CommandResult r =
      ecoforest("export " + (dir / "run").string() + " --out " + (dir / "b.glb").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("run.json: scenario.fingerprint: the scenario"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("has changed since this run"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.glb"));
}

// A run of the default scenario with binary snapshots (`snapshot_format = "binary"`): its
// snapshot exported as CSV is, byte for byte, the snapshot of the same run written as CSV,
// and `render` draws it as it draws any run.
TEST(ExportCommand, ABinarySnapshotExportsAsTheCsvSnapshotOfTheSameRun) {
  const auto dir = eco::test::freshDirectory("app_export_binary");
  std::string scenario =
      eco::test::readFile(std::filesystem::path(ECOFOREST_DATA_DIR) / "default.toml");
  const std::string species = "file = \"species/";
  for (std::size_t at = scenario.find(species); at != std::string::npos;
       at = scenario.find(species, at + 1))
    scenario.replace(at, species.size(),
                     "file = \"" + std::string(ECOFOREST_DATA_DIR) + "/species/");
  eco::test::writeFile(dir / "csv.toml", scenario);
  eco::test::writeFile(dir / "binary.toml", scenario + "snapshot_format = \"binary\"\n");
  for (const char* format : {"csv", "binary"}) {
    CommandResult r = ecoforest(fmt::format("run {}/{}.toml --years 12 --out {}/{}", dir.string(),
                                            format, dir.string(), format));
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "binary" / "trees" / "year_0010.bin"));
  EXPECT_FALSE(std::filesystem::exists(dir / "binary" / "trees" / "year_0010.csv"));
  CommandResult r = ecoforest("export " + (dir / "binary").string() + " --year 10 --out " +
                              (dir / "trees.csv").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string csv = eco::test::readFile(dir / "csv" / "trees" / "year_0010.csv");
  EXPECT_NE(r.output.find(fmt::format("year 10, {} trees as CSV rows",
                                      std::count(csv.begin(), csv.end(), '\n') - 1)),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(eco::test::readFile(dir / "trees.csv") == csv);
  CommandResult still =
      ecoforest("render " + (dir / "binary").string() + " --quality draft --size 160x90 --out " +
                (dir / "still.png").string());
  EXPECT_EQ(still.exitCode, 0) << still.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "still.png"));
}

TEST(ExportCommand, BadInputIsExitTwoAndWritesNothing) {
  const auto dir = eco::test::freshDirectory("app_export_bad");
  const std::string out = " --out " + (dir / "f.glb").string();
  CommandResult missing = ecoforest("export " + (dir / "nothing").string() + out);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("no such run folder"), std::string::npos) << missing.output;
  CommandResult year = ecoforest("export " + shortDefaultRun().string() + " --year 3" + out);
  EXPECT_EQ(year.exitCode, 2);
  EXPECT_NE(year.output.find("has: 10, 20"), std::string::npos) << year.output;
  CommandResult format =
      ecoforest("export " + shortDefaultRun().string() + " --out " + (dir / "f.obj").string());
  EXPECT_EQ(format.exitCode, 2);
  CommandResult folder = ecoforest("export " + shortDefaultRun().string() + " --out " +
                                   (dir / "no" / "f.glb").string());
  EXPECT_EQ(folder.exitCode, 2);
  CommandResult lods = ecoforest("export " + shortDefaultRun().string() + " --lod all" + out);
  EXPECT_EQ(lods.exitCode, 2);
  EXPECT_NE(lods.output.find("--instancing gpu"), std::string::npos) << lods.output;
  CommandResult mode =
      ecoforest("export " + shortDefaultRun().string() + " --instancing cpu" + out);
  EXPECT_EQ(mode.exitCode, 2);
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
}

}  // namespace
