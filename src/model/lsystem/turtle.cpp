#include "model/lsystem/turtle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/error.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"

namespace eco {
namespace {}  // namespace

Turtle::Turtle(const LSystem& system) : system_(system) {
  state_.width = system.turtle.width;
}

void Turtle::rotate(glm::dvec3& a, glm::dvec3& b, double angle_deg) {
  const double angle = radians(angle_deg);
  const double c = std::cos(angle), s = std::sin(angle);
  const glm::dvec3 a2 = a * c + b * s;
  b = glm::normalize(b * c - a * s);
  a = glm::normalize(a2);
}

void Turtle::applyTropism() {
  const TurtleSettings& t = system_.turtle;
  if (t.tropismStrength == 0.0) return;
  const glm::dvec3 target = glm::normalize(t.tropism);
  glm::dvec3 axis = glm::cross(state_.heading, target);
  const double sine = glm::length(axis);
  if (sine < 1e-9) return;
  axis /= sine;
  // ABOP eq. (2.1): the turn is e |H x T|.
  const double angle = t.tropismStrength * sine;
  state_.heading = glm::normalize(rotateAbout(state_.heading, axis, angle));
  state_.left = rotateAbout(state_.left, axis, angle);
  state_.up = glm::normalize(glm::cross(state_.heading, state_.left));
  state_.left = glm::cross(state_.up, state_.heading);
}

double Turtle::parameter(Symbol symbol, const double* params, int count, double fallback) const {
  if (count == 0) return fallback;
  // 1/0 or sqrt(-1) in a grammar would put NaN into every later position and mesh.
  if (!std::isfinite(params[0]))
    throw InputError({system_.file, 0, ""},
                     "the derived string has " + symbolName(symbol) + "(" +
                         std::to_string(params[0]) +
                         "): the turtle's parameters must be finite numbers");
  return params[0];
}

Turtle::Action Turtle::apply(Symbol symbol, const double* params, int count) {
  const TurtleSettings& t = system_.turtle;
  auto angle = [&] { return parameter(symbol, params, count, t.angle_deg); };
  TurtleState& s = state_;
  switch (symbol) {
    case 'F':
    case 'f': {
      moved_ = parameter(symbol, params, count, t.step);
      s.position += s.heading * moved_;
      if (symbol == 'F') {
        applyTropism();
        return Action::Draw;
      }
      s.branchStart = true;  // a gap: what is drawn next starts a new tube
      return Action::Move;
    }
    case '+':
      rotate(s.heading, s.left, angle());  // turn left about U
      return Action::None;
    case '-':
      rotate(s.heading, s.left, -angle());
      return Action::None;
    case '&':
      rotate(s.heading, s.up, -angle());  // pitch down about L
      return Action::None;
    case '^':
      rotate(s.heading, s.up, angle());
      return Action::None;
    case '\\':
      rotate(s.left, s.up, angle());  // roll left about H
      return Action::None;
    case '/':
      rotate(s.left, s.up, -angle());
      return Action::None;
    case '|':
      s.heading = -s.heading;  // turn around about U
      s.left = -s.left;
      return Action::None;
    case '$': {  // roll about H until L is horizontal (ABOP eq. 1.4)
      const glm::dvec3 l = glm::cross(glm::dvec3(0.0, 1.0, 0.0), s.heading);
      if (glm::length(l) < 1e-9) return Action::None;
      s.left = glm::normalize(l);
      s.up = glm::cross(s.heading, s.left);
      return Action::None;
    }
    case '!':
      s.width =
          count > 0 ? std::max(0.0, parameter(symbol, params, count, 0.0)) : s.width * t.widthScale;
      return Action::None;
    case '[':
      stack_.push_back(s);
      s.branchStart = true;
      return Action::Push;
    case ']':
      if (stack_.empty()) return Action::None;
      s = stack_.back();
      stack_.pop_back();
      return Action::Pop;
    case '{':
      return Action::PolygonBegin;
    case '}':
      return Action::PolygonEnd;
    default:
      return system_.leaves[symbol] ? Action::Leaf : Action::None;
  }
}

namespace {

constexpr std::uint64_t kInterpretPurpose = purpose("lsystem.interpret");

// ABOP's interpretation homomorphism: the modules the turtle draws for module i, through
// the first INTERPRETATION rule that matches it, or the module itself.
class Homomorphism {
 public:
  explicit Homomorphism(const LSystem& system) : system_(system) {
    std::size_t slots = 1;
    for (const Production& p : system.interpretations)
      slots = std::max(slots, static_cast<std::size_t>(p.slotCount));
    slots_.resize(slots);
  }

  template <typename Draw>
  void expand(const ModuleString& string, std::size_t i, Draw draw) {
    const Module& m = string.modules[i];
    const double* params = string.paramsOf(m);
    for (std::uint32_t r : system_.interpretationsBySymbol[m.symbol]) {
      const Production& p = system_.interpretations[r];
      if (p.strict.slots.size() != m.paramCount) continue;
      for (std::size_t k = 0; k < p.strict.slots.size(); ++k) slots_[p.strict.slots[k]] = params[k];
      const VariableDeviates deviates(system_.variables, streamKey(i, kInterpretPurpose));
      EvalEnv env;
      env.slots = slots_.data();
      env.deviates = &deviates;
      if (p.condition && !holds(*p.condition, env)) continue;
      scratch_.clear();
      instantiate(p.successor, env, scratch_);
      for (const Module& out : scratch_.modules)
        draw(out.symbol, scratch_.paramsOf(out), static_cast<int>(out.paramCount));
      return;
    }
    draw(m.symbol, params, static_cast<int>(m.paramCount));
  }

 private:
  const LSystem& system_;
  std::vector<double> slots_;
  ModuleString scratch_;
};

class SkeletonBuilder {
 public:
  SkeletonBuilder(const LSystem& system, TreeSkeleton& out)
      : system_(system), turtle_(system), out_(out) {}

  void interpret(const ModuleString& string) {
    Homomorphism homomorphism(system_);
    for (std::size_t i = 0; i < string.size(); ++i)
      homomorphism.expand(string, i, [this](Symbol symbol, const double* params, int count) {
        draw(symbol, params, count);
      });
    finishSkeleton();
  }

  InterpretStats stats;

 private:
  void draw(Symbol symbol, const double* params, int count) {
    const TurtleState before = turtle_.state();
    switch (turtle_.apply(symbol, params, count)) {
      case Turtle::Action::Draw:
        if (inPolygon_)
          polygonPoints_.push_back(turtle_.state().position);
        else if (turtle_.moved() > 0.0)
          addSegment(before);
        break;
      case Turtle::Action::Move:
        if (inPolygon_) polygonPoints_.push_back(turtle_.state().position);
        break;
      case Turtle::Action::Leaf:
        addLeaf(turtle_.state(), turtle_.parameter(symbol, params, count, system_.turtle.leafSize));
        break;
      case Turtle::Action::PolygonBegin:
        if (!inPolygon_) {  // nested polygons trace into the outer one
          inPolygon_ = true;
          polygonStart_ = turtle_.state();
          polygonPoints_.clear();
        }
        break;
      case Turtle::Action::PolygonEnd:
        if (inPolygon_) finishPolygon();
        break;
      default:
        break;
    }
  }

  // The segment the turtle just drew, moving from `before` along its heading.
  void addSegment(const TurtleState& before) {
    TurtleState& s = turtle_.state();
    BranchSegment segment;
    segment.start = glm::vec3(before.position);
    const glm::dvec3 h = before.heading;
    glm::dvec3 x = -before.left;
    x = glm::normalize(x - h * glm::dot(x, h));
    segment.frame = glm::mat3(glm::vec3(x), glm::vec3(h), glm::vec3(glm::cross(x, h)));
    segment.length_m = static_cast<float>(turtle_.moved());
    segment.startRadius_m = static_cast<float>(0.5 * before.width);
    segment.parent = before.segment;
    const bool continues = !before.branchStart && before.segment >= 0 &&
                           !hasContinuation_[static_cast<std::size_t>(before.segment)];
    segment.continuesParent = continues;
    if (continues) hasContinuation_[static_cast<std::size_t>(before.segment)] = true;
    s.segment = static_cast<std::int32_t>(out_.segments.size());
    s.branchStart = false;
    out_.segments.push_back(segment);
    hasContinuation_.push_back(false);
  }

  void addLeaf(const TurtleState& s, double size) {
    if (s.segment < 0 || size <= 0.0) {
      ++stats.droppedLeaves;
      return;
    }
    Leaf leaf;
    leaf.position = glm::vec3(s.position);
    leaf.direction = glm::vec3(s.heading);
    leaf.normal = glm::vec3(s.up);
    leaf.size_m = static_cast<float>(size);
    leaf.segment = s.segment;
    out_.leaves.push_back(leaf);
  }

  // A traced polygon becomes one leaf: from where the tracing began toward its farthest
  // point, as long as that distance, facing the turtle's up at the start.
  void finishPolygon() {
    inPolygon_ = false;
    double far = 0.0;
    glm::dvec3 tip = polygonStart_.position;
    for (const glm::dvec3& p : polygonPoints_) {
      const double d = glm::length(p - polygonStart_.position);
      if (d > far) {
        far = d;
        tip = p;
      }
    }
    if (far <= 0.0) return;
    TurtleState blade = polygonStart_;
    blade.segment = turtle_.state().segment;
    blade.heading = (tip - polygonStart_.position) / far;
    glm::dvec3 normal =
        polygonStart_.up - blade.heading * glm::dot(polygonStart_.up, blade.heading);
    if (glm::length(normal) < 1e-9) normal = polygonStart_.left;
    blade.up = glm::normalize(normal);
    addLeaf(blade, far);
  }

  // Radii where tubes meet, the pipe model, strands (tips below), Gravelius and Strahler
  // orders; children always follow their parents in the array.
  void finishSkeleton() {
    auto& segments = out_.segments;
    const std::size_t n = segments.size();
    std::vector<std::int32_t> strands(n, 0), strahler(n, 0), strahlerCount(n, 0);
    for (std::size_t i = n; i-- > 0;) {
      if (strands[i] == 0) strands[i] = 1;  // no children: a tip
      strahler[i] = strahlerCount[i] > 1 ? strahler[i] + 1 : std::max(strahler[i], 1);
      const std::int32_t parent = segments[i].parent;
      if (parent < 0) continue;
      strands[static_cast<std::size_t>(parent)] += strands[i];
      auto& best = strahler[static_cast<std::size_t>(parent)];
      auto& count = strahlerCount[static_cast<std::size_t>(parent)];
      if (strahler[i] > best) {
        best = strahler[i];
        count = 1;
      } else if (strahler[i] == best) {
        ++count;
      }
    }
    const double tipRadius = 0.5 * system_.turtle.width;
    for (std::size_t i = 0; i < n; ++i) {
      BranchSegment& s = segments[i];
      s.strands = strands[i];
      s.weibull = static_cast<std::int16_t>(std::min(strahler[i], 32767));
      if (s.parent >= 0) {
        const BranchSegment& p = segments[static_cast<std::size_t>(s.parent)];
        s.gravelius = static_cast<std::int16_t>(p.gravelius + (s.continuesParent ? 0 : 1));
      }
      if (system_.turtle.pipeModel)
        s.startRadius_m =
            static_cast<float>(tipRadius * std::sqrt(static_cast<double>(strands[i])));
      s.endRadius_m = s.startRadius_m;
    }
    for (std::size_t i = 0; i < n; ++i)
      if (segments[i].continuesParent)
        segments[static_cast<std::size_t>(segments[i].parent)].endRadius_m =
            segments[i].startRadius_m;
    stats.segments = n;
    stats.leaves = out_.leaves.size();
  }

  const LSystem& system_;
  Turtle turtle_;
  TreeSkeleton& out_;
  std::vector<bool> hasContinuation_;
  bool inPolygon_ = false;  // between { and }
  TurtleState polygonStart_;
  std::vector<glm::dvec3> polygonPoints_;
};

}  // namespace

TreeSkeleton interpretTree(const LSystem& system, const ModuleString& string,
                           InterpretStats* stats) {
  TreeSkeleton skeleton;
  SkeletonBuilder builder(system, skeleton);
  builder.interpret(string);
  deriveJoints(skeleton);
  if (stats) *stats = builder.stats;
  return skeleton;
}

bool applyEnvironment(const LSystem& system, ModuleString& string) {
  Turtle turtle(system);
  Homomorphism homomorphism(system);
  std::vector<bool> keep;
  bool cut = false;
  for (std::size_t i = 0; i < string.size(); ++i) {
    Module& m = string.modules[i];
    if (isQuery(m.symbol)) {
      const TurtleState& s = turtle.state();
      const glm::dvec3 value = m.symbol == kQueryPosition  ? s.position
                               : m.symbol == kQueryHeading ? s.heading
                               : m.symbol == kQueryUp      ? s.up
                                                           : s.left;
      double* params = string.params.data() + m.firstParam;
      for (int k = 0; k < std::min<int>(3, m.paramCount); ++k) params[k] = value[k];
      continue;
    }
    bool outside = false;
    homomorphism.expand(string, i, [&](Symbol symbol, const double* params, int count) {
      if (turtle.apply(symbol, params, count) == Turtle::Action::Draw)
        outside = outside || !system.prune.contains(turtle.state().position);
    });
    if (!outside) continue;
    // This F leaves the volume: it and the rest of its branch go; the ']' that closes the
    // branch stays and pops the turtle.
    if (keep.empty()) keep.assign(string.size(), true);
    const std::size_t end = branchEnd(string, i);
    std::fill(keep.begin() + static_cast<std::ptrdiff_t>(i),
              keep.begin() + static_cast<std::ptrdiff_t>(end), false);
    i = end;
    cut = true;
    if (i < string.size()) turtle.apply(']', nullptr, 0);
  }
  if (!cut) return false;
  ModuleString kept;
  for (std::size_t i = 0; i < string.size(); ++i)
    if (keep[i]) kept.append(string, i);
  string = std::move(kept);
  return true;
}

}  // namespace eco
