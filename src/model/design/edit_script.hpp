// A file of designer edits (`ecoforest design SPECIES --apply EDITS.toml`): the same actions
// the designer's window makes, for scripted species variations and for documentation
// screenshots. docs/designer.md describes the format:
//
//   [[edit]]
//   set = "kc"                     # a global parameter, or name, leaf_distribution,
//                                  # wind_direction
//   value = 0.5
//
//   [[edit]]
//   graph = "alpha_g_deg"          # a local graph, then one of
//   move = 1                       #   move point 1 to `to`
//   to = [7.5, 60]
//   # add = [10, 0.8]              #   add a point (a single number: on the line)
//   # remove = 1                   #   remove point 1
//
//   [[edit]]
//   undo = true                    # or redo = true
//
//   [hint]                         # optional: the visual hint the screenshot shows
//   graph = "alpha_g_deg"
//   point = 1                      # or segment = 0; neither: the whole graph
#pragma once

#include <filesystem>
#include <optional>
#include <variant>
#include <vector>

#include "core/error.hpp"
#include "model/design/design_session.hpp"

namespace eco {

struct UndoStep {};
struct RedoStep {};

struct ScriptedEdit {
  std::variant<EditAction, UndoStep, RedoStep> step;
  SourceLocation where;
};

struct HintRequest {
  LocalGraph graph = LocalGraph::KsG;
  std::optional<int> point, segment;
  SourceLocation where;
};

struct EditScript {
  std::vector<ScriptedEdit> edits;
  std::optional<HintRequest> hint;
};

// InputError at the file, line and key of a malformed entry.
EditScript loadEditScript(const std::filesystem::path& file);

// Applies every edit in order, one undo step each; an edit the species refuses (no such
// point) is an InputError at its entry, and an undo with nothing to undo is one too.
void applyEditScript(const EditScript& script, DesignSession& session);

}  // namespace eco
