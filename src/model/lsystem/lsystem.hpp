// Random L-systems (RL-systems) as the Green tool defines them (Lluch et al., section 2):
// parametric L-systems whose expressions may use random variables, with stochastic and
// context-sensitive productions, control modules and interrogation modules. This header
// holds the data: module strings, compiled productions and the system read from a grammar
// file (lsystem_parser.hpp). Derivation is in lsystem_deriver.hpp, the turtle that turns a
// string into a TreeSkeleton in lsystem_turtle.hpp. docs/lsystems.md describes the language.
#pragma once

#include <bitset>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "model/lsystem/expression.hpp"
#include "model/lsystem/random.hpp"

namespace eco {

// A module's symbol: one character (its code, below 128) or one of the named modules.
using Symbol = std::uint16_t;
inline constexpr Symbol kQueryPosition = 128;  // ?P(x,y,z)
inline constexpr Symbol kQueryHeading = 129;   // ?H(x,y,z)
inline constexpr Symbol kQueryUp = 130;        // ?U(x,y,z)
inline constexpr Symbol kQueryLeft = 131;      // ?L(x,y,z)
inline constexpr Symbol kSwitch = 132;         // @Switch(next){items}
inline constexpr Symbol kPendulum = 133;       // @Pendulum(direction){items}
inline constexpr Symbol kRepetition = 134;     // @Repetition(count){body}
inline constexpr Symbol kPrune = '%';          // also written @Prune
inline constexpr std::size_t kSymbolCount = 135;

// How a symbol is written in grammar files and printed strings ("A", "?P", "@Switch").
std::string symbolName(Symbol symbol);
bool isQuery(Symbol symbol);
bool isControl(Symbol symbol);  // Switch, Pendulum, Repetition: modules with a body

inline constexpr std::uint32_t kNoBody = std::numeric_limits<std::uint32_t>::max();

// 12 bytes: the string is an array of these plus one array of all parameters, so deriving
// copies flat memory.
struct Module {
  Symbol symbol = 0;
  std::uint16_t paramCount = 0;
  std::uint32_t firstParam = 0;  // index into ModuleString::params
  std::uint32_t body = kNoBody;  // control modules: index into ModuleString::bodies
};

struct ModuleString {
  std::vector<Module> modules;
  std::vector<double> params;
  std::vector<ModuleString> bodies;  // the lists and bodies of control modules

  std::size_t size() const { return modules.size(); }
  const double* paramsOf(const Module& m) const { return params.data() + m.firstParam; }
  double param(std::size_t module, int k) const {
    return params[modules[module].firstParam + static_cast<std::size_t>(k)];
  }
  // Appends a module without a body.
  void add(Symbol symbol, std::initializer_list<double> values = {});
  void add(Symbol symbol, const double* values, int count);
  // Appends a copy of module i of `from`, with its parameters and body.
  void append(const ModuleString& from, std::size_t i);
  void clear();
};

// Where the branch that holds module `from` ends: the index of the ']' that closes it,
// or the string's size for the main axis. Sub-branches opened on the way are skipped.
std::size_t branchEnd(const ModuleString& string, std::size_t from);

// The derived string as the issue's --print wants it: modules concatenated, parameters in
// shortest round-trip form, "A(1.5,2)B[+F]@Switch(1){AB}".
std::string toString(const ModuleString& string);

// ---- compiled productions ----

// A module of a successor (or axiom) whose parameters are expressions.
struct ModuleTemplate {
  Symbol symbol = 0;
  std::vector<Expression> params;
  int body = -1;  // index into StringTemplate::bodies
};

struct StringTemplate {
  std::vector<ModuleTemplate> modules;
  std::vector<StringTemplate> bodies;
  bool constant = false;  // no expression depends on anything: `prebuilt` is the result
  ModuleString prebuilt;  // filled when constant
};

// Appends the template with its expressions evaluated in `env`.
void instantiate(const StringTemplate& t, const EvalEnv& env, ModuleString& out);

// A module of a predecessor or context: its symbol and the slots its formal parameters
// bind to in the production's evaluation environment.
struct PatternModule {
  Symbol symbol = 0;
  std::vector<std::uint16_t> slots;
};

struct Production {
  int line = 0;                      // in the grammar file, for messages
  std::string text;                  // the production as written
  std::vector<PatternModule> left;   // left context, in string order
  PatternModule strict;              // the strict predecessor
  std::vector<PatternModule> right;  // right context, may hold [ and ]
  std::optional<Expression> condition;
  StringTemplate successor;
  int slotCount = 0;
  bool hasContext() const { return !left.empty() || !right.empty(); }
};

enum class PruneShape { None, Ellipsoid, Box };

// Green's Figs. 4-5: after every derivation step, a branch whose turtle leaves this volume
// is cut where it leaves.
struct PruneVolume {
  PruneShape shape = PruneShape::None;
  glm::dvec3 center{0.0};  // ellipsoid centre, or box minimum corner
  glm::dvec3 extent{0.0};  // ellipsoid radii, or box maximum corner
  bool contains(const glm::dvec3& p) const;
};

// Turtle defaults declared in the file (docs/lsystems.md, "Interpretation").
struct TurtleSettings {
  double step = 1.0;        // F and f without a parameter
  double angle_deg = 90.0;  // + - & ^ \ / without a parameter
  double width = 0.1;       // initial diameter
  double widthScale = 0.7;  // ! without a parameter multiplies the diameter by this
  double leafSize = 0.5;    // ~ and LEAF modules without a parameter
  glm::dvec3 tropism{0.0, -1.0, 0.0};
  double tropismStrength = 0.0;  // e: after each F, turn by e |H x T| toward T
  bool pipeModel = false;        // diameters from the number of tips (Leonardo's rule)
  double unit_m = 1.0;           // metres per turtle unit, for export and species
};

inline constexpr std::size_t kDefaultMaxModules = 50'000'000;
inline constexpr int kMaxIterations = 1000;

struct LSystem {
  std::string file;  // where it was read from, for messages
  std::string name;  // after SYSTEM, may be empty
  std::vector<RandomVariable> variables;
  StringTemplate axiom;
  std::vector<Production> productions;
  std::vector<std::vector<std::uint32_t>> rulesBySymbol =
      std::vector<std::vector<std::uint32_t>>(kSymbolCount);  // production indices, in order
  // INTERPRETATION: ABOP's interpretation homomorphism. The turtle draws a module through
  // the first of these that matches it (context-free, applied once, not recursively).
  std::vector<Production> interpretations;
  std::vector<std::vector<std::uint32_t>> interpretationsBySymbol =
      std::vector<std::vector<std::uint32_t>>(kSymbolCount);
  std::bitset<kSymbolCount> ignored;  // IGNORE: skipped when matching contexts
  std::bitset<kSymbolCount> leaves;   // ~ and LEAF symbols: drawn as leaves
  bool usesContext = false;
  bool usesQueries = false;
  bool usesPrune = false;  // some string holds %
  PruneVolume prune;
  TurtleSettings turtle;
  int iterations = 5;  // ITERATIONS: MaxIt when no count is given
  std::size_t maxModules = kDefaultMaxModules;
};

}  // namespace eco
