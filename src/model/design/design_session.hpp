// The tree designer's model (`ecoforest design`, docs/designer.md): the species being edited
// and the edits the paper's dialogs make (Zamuda et al., sections II.A and II.B) — set a
// global parameter, move, add or remove a control point of a local graph — with undo and
// redo. No window here: the designer's panels, its headless mode and the tests all edit
// through this class, and every edit clamps to the paper's bounds (species_schema.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "model/species.hpp"
#include "model/species_schema.hpp"

namespace eco {

struct SetGlobal {
  GlobalParameter parameter;
  double value;  // clamped to the parameter's valid range
};
// A new name for the species (a designed variety beside the original in one scenario);
// refused unless it is a plain name (core/names.hpp).
struct SetName {
  std::string name;
};
struct SetLeafDistribution {
  LeafDistribution distribution;
};
struct SetWindDirection {
  glm::dvec3 direction;  // w in the tree frame; its length does not matter, zero is refused
};
// The point keeps its place among its neighbours: x is clamped between theirs and to the
// graph's axis, y to the graph's bounds. Abscissae are not snapped to whole orders (the
// paper: snapping "would diminish flexibility").
struct MovePoint {
  LocalGraph graph;
  int index;
  double x, y;
};
// A new point at x (clamped to the axis), after any points at the same x; without y it is
// put on the line, so the graph does not change until the point is moved.
struct AddPoint {
  LocalGraph graph;
  double x;
  std::optional<double> y;
};
// Refused for a graph's last point: a graph needs one.
struct RemovePoint {
  LocalGraph graph;
  int index;
};
using EditAction = std::variant<SetGlobal, SetName, SetLeafDistribution, SetWindDirection,
                                MovePoint, AddPoint, RemovePoint>;

// An edit that does not fit the species as it is (no such point, the last point).
class EditRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class DesignSession {
 public:
  // An L-system species is refused (InputError): the designer edits the strand model.
  explicit DesignSession(Species species);

  const Species& species() const { return species_; }
  // Counts every change, undo and redo included: the preview rebuilds when it moves.
  std::uint64_t version() const { return version_; }

  // Applies an edit as one undo step. Edits with the same non-zero `gesture` in a row (the
  // moves of one drag) form one step together. Throws EditRefused.
  void apply(const EditAction& edit, std::uint64_t gesture = 0);
  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  bool undo();  // false when there is nothing to undo
  bool redo();

 private:
  // Takes the newest state of `from` back, keeping the current one on `to` (undo: from the
  // undo stack to the redo stack; redo the other way).
  bool stepBack(std::vector<Species>& from, std::vector<Species>& to);

  Species species_;
  std::vector<Species> undo_, redo_;
  std::uint64_t version_ = 0;
  std::uint64_t lastGesture_ = 0;
};

// What one edit does to a species (the session's step without the history).
void applyEdit(Species& species, const EditAction& edit);

}  // namespace eco
