// The 3D turtle that interprets an RL-system string (ABOP section 1.5; Lluch et al.,
// "Interpretation of strings"): F draws a branch segment, + - & ^ \ / | $ turn it, [ ] push
// and pop its state, ! sets the width, { } trace a leaf blade, ~ and LEAF modules place
// leaves, and after every F the heading bends toward the tropism vector. The result is a
// TreeSkeleton, the currency the mesher, levels of detail and exporters share.
// Coordinates: y up; the turtle starts at the origin heading up (H = +y, L = -x, U = +z).
#pragma once

#include <glm/vec3.hpp>

#include "model/lsystem/lsystem.hpp"
#include "model/skeleton.hpp"

namespace eco {

struct TurtleState {
  glm::dvec3 position{0.0};
  glm::dvec3 heading{0.0, 1.0, 0.0};  // H
  glm::dvec3 left{-1.0, 0.0, 0.0};    // L
  glm::dvec3 up{0.0, 0.0, 1.0};       // U = H x L
  double width = 0.1;                 // diameter
  std::int32_t segment = -1;          // the last segment this branch drew
  bool branchStart = true;            // nothing drawn since the branch began (or a move)
};

class Turtle {
 public:
  explicit Turtle(const LSystem& system);

  enum class Action { None, Draw, Move, Leaf, Push, Pop, PolygonBegin, PolygonEnd };
  // Interprets one module (queries and control modules do nothing). For Draw and Move,
  // moved() is the distance; the state after the call is the new one.
  Action apply(Symbol symbol, const double* params, int count);
  double moved() const { return moved_; }
  // A module's first parameter (a length, angle, width or leaf size), or `fallback` when
  // it has none; a non-finite value is an InputError.
  double parameter(Symbol symbol, const double* params, int count, double fallback) const;
  const TurtleState& state() const { return state_; }
  TurtleState& state() { return state_; }

 private:
  void rotate(glm::dvec3& a, glm::dvec3& b, double angle_deg);  // a toward b
  void applyTropism();

  const LSystem& system_;
  TurtleState state_;
  std::vector<TurtleState> stack_;
  double moved_ = 0.0;
};

struct InterpretStats {
  std::size_t segments = 0;
  std::size_t leaves = 0;
  std::size_t droppedLeaves = 0;  // leaves placed before any wood: nothing to carry them
};

// The skeleton of a derived string, in turtle units (the caller scales by UNIT).
TreeSkeleton interpretTree(const LSystem& system, const ModuleString& string,
                           InterpretStats* stats = nullptr);

// After each derivation step (Lluch et al.): fills ?P ?H ?U ?L with the turtle's position
// and orientation there, and cuts each branch where it leaves the PRUNE volume (the F that
// leaves and the rest of its branch go). Returns whether anything was cut.
bool applyEnvironment(const LSystem& system, ModuleString& string);

}  // namespace eco
