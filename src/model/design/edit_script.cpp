#include "model/design/edit_script.hpp"

#include <string>

#include "core/names.hpp"
#include "core/toml_reader.hpp"

namespace eco {
namespace {

std::vector<std::string> globalKeys() {
  std::vector<std::string> keys;
  for (const GlobalParameterInfo& info : globalParameters()) keys.emplace_back(info.key);
  keys.emplace_back("name");
  keys.emplace_back("leaf_distribution");
  keys.emplace_back("wind_direction");
  return keys;
}

std::vector<std::string> graphKeys() {
  std::vector<std::string> keys;
  for (const LocalGraphInfo& info : localGraphs()) keys.emplace_back(info.key);
  return keys;
}

LocalGraph graphNamed(TomlTable& table, std::string_view key) {
  const std::string name = table.string(key);
  if (std::optional<LocalGraph> graph = findLocalGraph(name)) return *graph;
  table.fail(key, "unknown graph '" + name + "'" + didYouMean(name, graphKeys()));
}

EditAction setEdit(TomlTable& entry) {
  const std::string name = entry.string("set");
  if (name == "leaf_distribution") {
    const std::string value = entry.string("value");
    if (std::optional<LeafDistribution> d = leafDistributionNamed(value))
      return SetLeafDistribution{*d};
    entry.fail("value", "unknown leaf distribution '" + value +
                            "' (expected spiral, stacked, staggered, bunched or coniferous)");
  }
  if (name == "name") return SetName{entry.string("value")};
  if (name == "wind_direction") {
    const std::vector<double> w = entry.numbers("value", 3);
    return SetWindDirection{{w[0], w[1], w[2]}};
  }
  if (std::optional<GlobalParameter> parameter = findGlobalParameter(name))
    return SetGlobal{*parameter, entry.number("value")};
  entry.fail("set", "unknown parameter '" + name + "'" + didYouMean(name, globalKeys()));
}

EditAction graphEdit(TomlTable& entry) {
  const LocalGraph graph = graphNamed(entry, "graph");
  const int actions = entry.has("move") + entry.has("add") + entry.has("remove");
  if (actions != 1) entry.fail("graph", "give exactly one of move (with to), add or remove");
  if (entry.has("move")) {
    const auto index = static_cast<int>(entry.integer("move", {}, {0, 1e6}));
    const std::vector<double> to = entry.numbers("to", 2);
    return MovePoint{graph, index, to[0], to[1]};
  }
  if (entry.has("add")) {
    const std::vector<double> at = entry.numberList("add");
    if (at.size() > 2) entry.fail("add", "expected [x] or [x, y]");
    return AddPoint{graph, at[0], at.size() == 2 ? std::optional<double>(at[1]) : std::nullopt};
  }
  return RemovePoint{graph, static_cast<int>(entry.integer("remove", {}, {0, 1e6}))};
}

ScriptedEdit parseEntry(TomlTable& entry) {
  const int kinds = entry.has("set") + entry.has("graph") + entry.has("undo") + entry.has("redo");
  if (kinds != 1) entry.fail("", "an [[edit]] has exactly one of set, graph, undo or redo");
  ScriptedEdit edit;
  if (entry.has("set")) {
    edit.where = entry.where("set");
    edit.step = setEdit(entry);
  } else if (entry.has("graph")) {
    edit.where = entry.where("graph");
    edit.step = graphEdit(entry);
  } else {
    const bool undo = entry.has("undo");
    const char* key = undo ? "undo" : "redo";
    edit.where = entry.where(key);
    if (!entry.boolean(key)) entry.fail(key, "write `" + std::string(key) + " = true`");
    if (undo)
      edit.step = UndoStep{};
    else
      edit.step = RedoStep{};
  }
  entry.finish();
  return edit;
}

}  // namespace

EditScript loadEditScript(const std::filesystem::path& file) {
  TomlDocument document = TomlDocument::load(file);
  TomlTable root = document.root();
  EditScript script;
  for (TomlTable& entry : root.tables("edit")) script.edits.push_back(parseEntry(entry));
  if (std::optional<TomlTable> hint = root.table("hint")) {
    HintRequest request;
    request.where = hint->where("graph");
    request.graph = graphNamed(*hint, "graph");
    if (hint->has("point") && hint->has("segment"))
      hint->fail("segment", "give point or segment, not both");
    if (hint->has("point")) request.point = static_cast<int>(hint->integer("point", {}, {0, 1e6}));
    if (hint->has("segment"))
      request.segment = static_cast<int>(hint->integer("segment", {}, {0, 1e6}));
    hint->finish();
    script.hint = request;
  }
  root.finish();
  return script;
}

void applyEditScript(const EditScript& script, DesignSession& session) {
  for (const ScriptedEdit& edit : script.edits) {
    if (std::holds_alternative<UndoStep>(edit.step)) {
      if (!session.undo()) throw InputError(edit.where, "there is no edit to undo");
    } else if (std::holds_alternative<RedoStep>(edit.step)) {
      if (!session.redo()) throw InputError(edit.where, "there is no undone edit to redo");
    } else {
      try {
        session.apply(std::get<EditAction>(edit.step));
      } catch (const EditRefused& refused) {
        throw InputError(edit.where, refused.what());
      }
    }
  }
}

}  // namespace eco
