#include "model/lsystem/parser.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/binary_io.hpp"
#include "core/error.hpp"

namespace eco {
namespace {

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// Characters that are modules on their own. Excluded: what the syntax itself uses.
bool isModuleChar(char c) {
  if (c <= ' ' || c > '~') return false;
  switch (c) {
    case '(':
    case ')':
    case ',':
    case ':':
    case '<':
    case '>':
    case '#':
    case '@':
    case '?':
    case '=':
    case ';':
      return false;
    default:
      return true;
  }
}

struct Line {
  std::string_view text;  // without its comment
  int number = 0;
};

class GrammarParser {
 public:
  GrammarParser(std::string_view text, const std::string& fileName) : file_(fileName) {
    system_.file = fileName;
    int number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(start, end - start);
      ++number;
      line = line.substr(0, std::min(line.find('#'), line.size()));
      lines_.push_back({line, number});
      if (end == text.size()) break;
      start = end + 1;
    }
  }

  LSystem parse() {
    enum class Section {
      Start,
      Declarations,
      Axiom,
      Rules,
      Interpretation,
      End
    } section = Section::Start;
    int axiomLines = 0;
    for (const Line& line : lines_) {
      TextCursor cursor(line.text, file_, line.number);
      cursor.skipSpace();
      if (cursor.atEnd()) continue;
      if (section == Section::End) cursor.fail("text after END.");
      const std::size_t mark = cursor.position();
      const std::string word = upper(cursor.identifier());
      cursor.skipSpace();
      if (word == "SYSTEM" && section == Section::Start) {
        system_.name = std::string(cursor.text().substr(cursor.position()));
        while (!system_.name.empty() &&
               std::isspace(static_cast<unsigned char>(system_.name.back())))
          system_.name.pop_back();
        section = Section::Declarations;
        continue;
      }
      if (section == Section::Start) cursor.failAt(1, "a grammar starts with SYSTEM");
      if (word == "DECLARATIONS" && section == Section::Declarations && cursor.atEnd()) continue;
      if (word == "AXIOM" && section == Section::Declarations && cursor.atEnd()) {
        section = Section::Axiom;
        continue;
      }
      if (word == "RULES" && section == Section::Axiom && cursor.atEnd()) {
        if (axiomLines == 0) cursor.failAt(1, "the AXIOM is empty");
        section = Section::Rules;
        continue;
      }
      if (word == "INTERPRETATION" && section == Section::Rules && cursor.atEnd()) {
        section = Section::Interpretation;
        continue;
      }
      if (word == "END" && (section == Section::Rules || section == Section::Axiom ||
                            section == Section::Interpretation)) {
        cursor.accept(".");
        if (!cursor.atEnd()) cursor.fail("unexpected text after END.");
        if (section == Section::Axiom && axiomLines == 0) cursor.failAt(1, "the AXIOM is empty");
        section = Section::End;
        continue;
      }
      cursor.seek(mark);
      switch (section) {
        case Section::Declarations:
          declaration(cursor);
          break;
        case Section::Axiom:
          axiomLine(cursor);
          ++axiomLines;
          break;
        case Section::Rules:
          production(cursor, system_.productions, false);
          break;
        case Section::Interpretation:
          production(cursor, system_.interpretations, true);
          break;
        default:
          break;
      }
    }
    const int last = lines_.empty() ? 1 : lines_.back().number;
    if (section == Section::Start)
      throw InputError({file_, last, "", 1}, "empty grammar: expected SYSTEM");
    if (section == Section::Declarations)
      throw InputError({file_, last, "", 1}, "missing AXIOM section");
    if (section != Section::End) throw InputError({file_, last, "", 1}, "missing END.");
    finish();
    return std::move(system_);
  }

 private:
  // ---- declarations ----
  void declaration(TextCursor& cursor) {
    const int column = cursor.column();
    const std::string word = upper(cursor.identifier());
    if (word == "CONTINUOUS" || word == "DISCRETE") return randomVariable(cursor, word);
    if (word == "IGNORE") return symbolList(cursor, system_.ignored, "IGNORE");
    if (word == "LEAF") return symbolList(cursor, system_.leaves, "LEAF");
    if (word == "DEFINE") return define(cursor);
    TurtleSettings& t = system_.turtle;
    if (word == "ITERATIONS") {
      system_.iterations = static_cast<int>(integerValue(cursor, 0, kMaxIterations));
    } else if (word == "MAXMODULES") {
      system_.maxModules = static_cast<std::size_t>(integerValue(cursor, 1, 2'000'000'000));
    } else if (word == "STEP") {
      t.step = numberValue(cursor, 0.0, 1e6);
    } else if (word == "ANGLE") {
      t.angle_deg = numberValue(cursor, -360.0, 360.0);
    } else if (word == "WIDTH") {
      t.width = numberValue(cursor, 0.0, 1e6);
    } else if (word == "WIDTH_SCALE") {
      t.widthScale = numberValue(cursor, 0.0, 1.0);
    } else if (word == "LEAF_SIZE") {
      t.leafSize = numberValue(cursor, 0.0, 1e6);
    } else if (word == "UNIT") {
      t.unit_m = numberValue(cursor, 1e-6, 1e6);
      if (t.unit_m <= 0.0) cursor.fail("UNIT must be positive");
    } else if (word == "PIPE_MODEL") {
      t.pipeModel = true;
    } else if (word == "TROPISM") {
      glm::dvec3 v;
      for (int k = 0; k < 3; ++k) v[k] = numberValue(cursor, -1e6, 1e6);
      if (v == glm::dvec3(0.0)) cursor.fail("the TROPISM vector must not be zero");
      t.tropism = v;
      t.tropismStrength = numberValue(cursor, -10.0, 10.0);
    } else if (word == "PRUNE") {
      prune(cursor);
    } else {
      cursor.failAt(column,
                    "unknown declaration '" + word +
                        "' (expected CONTINUOUS, DISCRETE, IGNORE, DEFINE, ITERATIONS, STEP, "
                        "ANGLE, WIDTH, WIDTH_SCALE, LEAF, LEAF_SIZE, TROPISM, PIPE_MODEL, UNIT, "
                        "PRUNE or MAXMODULES)");
    }
    endOfLine(cursor);
  }

  void endOfLine(TextCursor& cursor) {
    cursor.skipSpace();
    if (!cursor.atEnd()) cursor.fail(std::string("unexpected '") + cursor.peek() + "'");
  }

  // A constant expression (numbers, DEFINEs, functions).
  double constant(TextCursor& cursor) {
    const int column = (cursor.skipSpace(), cursor.column());
    ExpressionScope scope;
    scope.defines = &defines_;
    Expression e = parseExpression(cursor, scope);
    if (!e.isConstant()) cursor.failAt(column, "expected a constant");
    return e.code[0].value;
  }

  double numberValue(TextCursor& cursor, double lo, double hi) {
    cursor.accept(",");
    const int column = (cursor.skipSpace(), cursor.column());
    // A declaration's numbers are separated by spaces: read one term, not "1 -2" as 1-2.
    std::size_t end = cursor.position();
    const std::string_view text = cursor.text();
    int depth = 0;
    while (end < text.size() &&
           (depth > 0 || (text[end] != ' ' && text[end] != '\t' && text[end] != ','))) {
      depth += text[end] == '(' ? 1 : text[end] == ')' ? -1 : 0;
      ++end;
    }
    TextCursor term(text.substr(0, end), cursor.file(), cursor.line());
    term.seek(cursor.position());
    const double value = constant(term);
    if (!term.atEnd()) term.fail("unexpected text in a number");
    cursor.seek(end);
    if (!(value >= lo && value <= hi))
      cursor.failAt(column, "value " + std::to_string(value) + " out of range [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return value;
  }

  double integerValue(TextCursor& cursor, double lo, double hi) {
    const int column = (cursor.skipSpace(), cursor.column());
    const double value = numberValue(cursor, lo, hi);
    if (value != std::floor(value)) cursor.failAt(column, "expected an integer");
    return value;
  }

  void randomVariable(TextCursor& cursor, const std::string& kind) {
    RandomVariable v;
    v.discrete = kind == "DISCRETE";
    const int nameColumn = (cursor.skipSpace(), cursor.column());
    v.name = cursor.identifier();
    if (v.name.empty()) cursor.fail("expected the variable's name");
    checkNewName(cursor, v.name, nameColumn);
    const int column = (cursor.skipSpace(), cursor.column());
    const std::string distribution = upper(cursor.identifier());
    if (!distributionFromName(distribution, v.distribution))
      cursor.failAt(column, "unknown distribution '" + distribution +
                                "' (expected CONSTANT, UNIFORM, EXPONENTIAL, NORMAL, BINOMIAL or "
                                "POISSON)");
    cursor.expect("(", "after the distribution");
    v.a = constant(cursor);
    if (distributionArity(v.distribution) == 2) {
      cursor.expect(",", "between the distribution's two parameters");
      v.b = constant(cursor);
    }
    cursor.expect(")", "after the distribution's parameters");
    if (std::string why = checkRandomVariable(v); !why.empty()) cursor.failAt(column, why);
    system_.variables.push_back(v);
    endOfLine(cursor);
  }

  void define(TextCursor& cursor) {
    const int column = (cursor.skipSpace(), cursor.column());
    std::string name = cursor.identifier();
    if (name.empty()) cursor.fail("expected the constant's name");
    checkNewName(cursor, name, column);
    cursor.accept("=");
    const double value = constant(cursor);
    defines_.emplace_back(name, value);
    endOfLine(cursor);
  }

  void checkNewName(TextCursor& cursor, const std::string& name, int column) {
    bool taken = name == "NumIt" || name == "MaxIt" || name == "pi" || name == "PI";
    for (const auto& [defined, value] : defines_) taken = taken || defined == name;
    for (const RandomVariable& v : system_.variables) taken = taken || v.name == name;
    if (taken) cursor.failAt(column, "'" + name + "' is already defined");
  }

  void symbolList(TextCursor& cursor, std::bitset<kSymbolCount>& set, const char* what) {
    cursor.skipSpace();
    if (cursor.atEnd()) cursor.fail(std::string(what) + " needs at least one module symbol");
    while (cursor.skipSpace(), !cursor.atEnd()) set.set(symbol(cursor));
  }

  void prune(TextCursor& cursor) {
    const int column = (cursor.skipSpace(), cursor.column());
    const std::string shape = upper(cursor.identifier());
    PruneVolume& v = system_.prune;
    if (shape == "ELLIPSOID")
      v.shape = PruneShape::Ellipsoid;
    else if (shape == "BOX")
      v.shape = PruneShape::Box;
    else
      cursor.failAt(column, "unknown pruning shape '" + shape + "' (expected ELLIPSOID or BOX)");
    cursor.expect("(", "after the shape");
    double values[6];
    for (int k = 0; k < 6; ++k) {
      if (k > 0) cursor.expect(",", "between the shape's six numbers");
      values[k] = constant(cursor);
    }
    cursor.expect(")", "after the shape's six numbers");
    v.center = {values[0], values[1], values[2]};
    v.extent = {values[3], values[4], values[5]};
    if (v.shape == PruneShape::Ellipsoid && !(v.extent.x > 0 && v.extent.y > 0 && v.extent.z > 0))
      cursor.failAt(column, "ELLIPSOID(cx, cy, cz, rx, ry, rz) needs positive radii");
    if (v.shape == PruneShape::Box &&
        !(v.extent.x > v.center.x && v.extent.y > v.center.y && v.extent.z > v.center.z))
      cursor.failAt(column, "BOX(x0, y0, z0, x1, y1, z1) needs x0 < x1, y0 < y1, z0 < z1");
  }

  // ---- modules ----

  // One module symbol (no parameters), at the cursor.
  Symbol symbol(TextCursor& cursor) {
    cursor.skipSpace();
    const int column = cursor.column();
    const char c = cursor.peek();
    if (c == '?') {
      cursor.next();
      switch (cursor.next()) {
        case 'P':
          return kQueryPosition;
        case 'H':
          return kQueryHeading;
        case 'U':
          return kQueryUp;
        case 'L':
          return kQueryLeft;
        default:
          cursor.failAt(column, "an interrogation module is ?P, ?H, ?U or ?L");
      }
    }
    if (c == '@') {
      cursor.next();
      const std::string name = cursor.identifier();
      if (name == "Switch") return kSwitch;
      if (name == "Pendulum") return kPendulum;
      if (name == "Repetition") return kRepetition;
      if (name == "Prune") return kPrune;
      cursor.failAt(column, "unknown control module '@" + name +
                                "' (expected @Switch, @Pendulum, @Repetition or @Prune)");
    }
    if (!isModuleChar(c)) {
      if (cursor.atEnd()) cursor.fail("expected a module but the line ends");
      cursor.fail(std::string("'") + c + "' is not a module symbol");
    }
    cursor.next();
    return static_cast<Symbol>(c);
  }

  // Whether a module string goes on: not at the end and not at a separator.
  static bool moreModules(TextCursor& cursor, bool inBody) {
    cursor.skipSpace();
    if (cursor.atEnd()) return false;
    const char c = cursor.peek();
    if (inBody && c == '}') return false;
    if (c == '-' && cursor.peek(1) == '>') return false;
    if (c == '\xe2') return false;  // the UTF-8 arrow
    return c != '<' && c != '>' && c != ':';
  }

  // A successor or axiom: modules whose parameters are expressions.
  StringTemplate stringTemplate(TextCursor& cursor, const ExpressionScope& scope, bool inBody,
                                bool balanced = true) {
    StringTemplate out;
    std::vector<int> open;  // columns of unclosed '['
    while (moreModules(cursor, inBody)) {
      const int column = cursor.column();
      ModuleTemplate m;
      m.symbol = symbol(cursor);
      if (m.symbol == '[') open.push_back(column);
      if (m.symbol == ']') {
        if (open.empty() && balanced) cursor.failAt(column, "']' closes no '['");
        if (!open.empty()) open.pop_back();
      }
      if (cursor.accept("(")) {
        if (!cursor.accept(")")) {
          do m.params.push_back(parseExpression(cursor, scope));
          while (cursor.accept(","));
          cursor.expect(")", "to close the parameter list");
        }
      }
      if (m.params.size() > 255) cursor.failAt(column, "more than 255 parameters");
      if (isControl(m.symbol)) controlModule(cursor, scope, m, out, column);
      if (isQuery(m.symbol) && m.params.size() != 3 && !m.params.empty())
        cursor.failAt(column, symbolName(m.symbol) + " has three parameters (x, y, z)");
      if (isQuery(m.symbol) && m.params.empty())
        m.params.assign(3, Expression{{ExprInstr{}}});  // filled by the turtle
      out.modules.push_back(std::move(m));
    }
    if (!open.empty() && balanced) cursor.failAt(open.back(), "'[' is never closed");
    return out;
  }

  void controlModule(TextCursor& cursor, const ExpressionScope& scope, ModuleTemplate& m,
                     StringTemplate& out, int column) {
    const std::string name = symbolName(m.symbol);
    if (m.symbol == kRepetition && m.params.size() != 1)
      cursor.failAt(column, "@Repetition(count){body} takes one parameter, the count");
    if (m.symbol != kRepetition && m.params.size() > 1)
      cursor.failAt(column, name + " takes at most one parameter");
    if (m.params.empty())  // Switch starts at item 0; Pendulum goes forward first
      m.params.push_back(
          Expression{{ExprInstr{ExprOp::Const, 0, 0, 0, m.symbol == kPendulum ? 1.0 : 0.0}}});
    cursor.expect("{", "to open the body of " + name);
    const int bodyColumn = cursor.column();
    if (++bodyNesting_ > kMaxBodyNesting)  // derivation recurses into bodies: bound it
      cursor.failAt(column, "control modules nested more than 32 deep");
    StringTemplate body = stringTemplate(cursor, scope, true);
    --bodyNesting_;
    cursor.expect("}", "to close the body of " + name);
    if (body.modules.empty()) cursor.failAt(bodyColumn, name + " needs at least one module");
    if (m.symbol != kRepetition)
      for (const ModuleTemplate& item : body.modules)
        if (item.symbol == '[' || item.symbol == ']' || isControl(item.symbol))
          cursor.failAt(bodyColumn, name +
                                        " lists single modules: no brackets or control "
                                        "modules inside");
    m.body = static_cast<int>(out.bodies.size());
    out.bodies.push_back(std::move(body));
  }

  // A predecessor or context: modules whose parameters are formal names.
  std::vector<PatternModule> pattern(TextCursor& cursor, std::vector<std::string>& slots) {
    std::vector<PatternModule> out;
    while (moreModules(cursor, false)) {
      PatternModule m;
      const int column = cursor.column();
      m.symbol = symbol(cursor);
      if (isControl(m.symbol))
        cursor.failAt(column, "control modules cannot be matched by a production");
      if (cursor.accept("(")) {
        do {
          const int nameColumn = (cursor.skipSpace(), cursor.column());
          std::string name = cursor.identifier();
          if (name.empty()) cursor.fail("expected a formal parameter name");
          if (std::find(slots.begin(), slots.end(), name) != slots.end())
            cursor.failAt(nameColumn, "formal parameter '" + name + "' appears twice");
          for (const auto& [defined, value] : defines_)
            if (defined == name) cursor.failAt(nameColumn, "'" + name + "' is a DEFINE");
          m.slots.push_back(static_cast<std::uint16_t>(slots.size()));
          slots.push_back(std::move(name));
        } while (cursor.accept(","));
        cursor.expect(")", "to close the formal parameters");
      }
      out.push_back(std::move(m));
    }
    return out;
  }

  void axiomLine(TextCursor& cursor) {
    ExpressionScope scope;
    scope.variables = &system_.variables;
    scope.defines = &defines_;
    scope.nextOccurrence = &axiomOccurrence_;
    StringTemplate part = stringTemplate(cursor, scope, false);
    if (!cursor.atEnd())
      cursor.fail(std::string("unexpected '") + cursor.peek() + "' in the axiom");
    const int offset = static_cast<int>(system_.axiom.bodies.size());
    for (ModuleTemplate& m : part.modules) {
      if (m.body >= 0) m.body += offset;
      system_.axiom.modules.push_back(std::move(m));
    }
    for (StringTemplate& b : part.bodies) system_.axiom.bodies.push_back(std::move(b));
  }

  // A production of RULES, or of INTERPRETATION (context-free, drawn once by the turtle:
  // its successor may open or close branches, as in ABOP's "[ -> [+(45)").
  void production(TextCursor& cursor, std::vector<Production>& target, bool interpretation) {
    Production p;
    p.line = cursor.line();
    std::string_view text = cursor.text();
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
      text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
      text.remove_suffix(1);
    p.text = std::string(text);

    std::vector<std::string> slots;
    const int start = (cursor.skipSpace(), cursor.column());
    std::vector<PatternModule> first = pattern(cursor, slots);
    if (cursor.accept("<")) {
      p.left = std::move(first);
      for (const PatternModule& m : p.left)
        if (m.symbol == '[' || m.symbol == ']')
          cursor.failAt(start, "a left context is a path: no brackets");
      const int strictColumn = (cursor.skipSpace(), cursor.column());
      first = pattern(cursor, slots);
      if (first.size() != 1)
        cursor.failAt(strictColumn, "the strict predecessor is exactly one module");
    } else if (first.size() != 1) {
      cursor.failAt(start, first.empty() ? "expected the predecessor module"
                                         : "the strict predecessor is one module; write "
                                           "contexts as lc < pred > rc");
    }
    p.strict = std::move(first.front());
    if (interpretation && !p.left.empty())
      cursor.failAt(start, "interpretation rules have no context");
    if (cursor.accept(">")) {
      if (interpretation) cursor.failAt(start, "interpretation rules have no context");
      const int rightColumn = (cursor.skipSpace(), cursor.column());
      p.right = pattern(cursor, slots);
      if (p.right.empty()) cursor.failAt(rightColumn, "expected a right context after '>'");
      int depth = 0;
      for (const PatternModule& m : p.right) {
        depth += m.symbol == '[' ? 1 : m.symbol == ']' ? -1 : 0;
        if (depth < -1) cursor.failAt(rightColumn, "unbalanced brackets in the right context");
      }
    }
    if (slots.size() > 1000) cursor.failAt(start, "too many formal parameters");
    ExpressionScope scope;
    scope.slots = &slots;
    scope.variables = &system_.variables;
    scope.defines = &defines_;
    if (cursor.accept(":")) {
      cursor.skipSpace();
      if (!(cursor.peek() == '-' && cursor.peek(1) == '>') && cursor.peek() != '\xe2')
        p.condition = parseExpression(cursor, scope);
    }
    if (!cursor.accept("->") && !cursor.accept("\xe2\x86\x92")) {
      cursor.skipSpace();
      cursor.fail(cursor.atEnd() ? "expected '->' but the line ends"
                                 : std::string("expected '->', found '") + cursor.peek() + "'");
    }
    std::uint32_t occurrence = 1;
    scope.nextOccurrence = &occurrence;
    const bool bracket = p.strict.symbol == '[' || p.strict.symbol == ']';
    const int successorColumn = (cursor.skipSpace(), cursor.column());
    p.successor = stringTemplate(cursor, scope, false, !interpretation && !bracket);
    if (!cursor.atEnd()) cursor.fail(std::string("unexpected '") + cursor.peek() + "'");
    // The lecture lists "[ -> [" and "] -> ]"; anything else would break the branching.
    if (bracket && !interpretation &&
        !(p.successor.modules.size() == 1 && p.successor.modules[0].symbol == p.strict.symbol))
      cursor.failAt(successorColumn, "a bracket can only be rewritten as itself");
    if (interpretation)
      for (const ModuleTemplate& m : p.successor.modules)
        if (isControl(m.symbol))
          cursor.failAt(successorColumn, "interpretation rules cannot make control modules");
    p.slotCount = static_cast<int>(slots.size());
    target.push_back(std::move(p));
  }

  static void prebuild(StringTemplate& t) {
    for (StringTemplate& body : t.bodies) prebuild(body);
    t.constant = std::all_of(t.modules.begin(), t.modules.end(), [](const ModuleTemplate& m) {
      return m.body < 0 && std::all_of(m.params.begin(), m.params.end(),
                                       [](const Expression& e) { return e.isConstant(); });
    });
    if (!t.constant) return;
    for (const ModuleTemplate& m : t.modules) {
      double values[256];
      for (std::size_t k = 0; k < m.params.size(); ++k) values[k] = m.params[k].code[0].value;
      t.prebuilt.add(m.symbol, values, static_cast<int>(m.params.size()));
    }
  }

  template <typename Test>
  static bool contains(const StringTemplate& t, Test test) {
    return std::any_of(t.modules.begin(), t.modules.end(),
                       [&](const ModuleTemplate& m) { return test(m.symbol); }) ||
           std::any_of(t.bodies.begin(), t.bodies.end(),
                       [&](const StringTemplate& body) { return contains(body, test); });
  }
  static bool hasQuery(const StringTemplate& t) { return contains(t, isQuery); }
  static bool hasPrune(const StringTemplate& t) {
    return contains(t, [](Symbol s) { return s == kPrune; });
  }

  void finish() {
    system_.leaves.set('~');
    prebuild(system_.axiom);
    system_.usesQueries = hasQuery(system_.axiom);
    system_.usesPrune = hasPrune(system_.axiom);
    for (std::size_t i = 0; i < system_.productions.size(); ++i) {
      Production& p = system_.productions[i];
      prebuild(p.successor);
      system_.rulesBySymbol[p.strict.symbol].push_back(static_cast<std::uint32_t>(i));
      system_.usesContext = system_.usesContext || p.hasContext();
      system_.usesQueries = system_.usesQueries || hasQuery(p.successor);
      system_.usesPrune = system_.usesPrune || hasPrune(p.successor);
    }
    for (std::size_t i = 0; i < system_.interpretations.size(); ++i) {
      Production& p = system_.interpretations[i];
      prebuild(p.successor);
      system_.interpretationsBySymbol[p.strict.symbol].push_back(static_cast<std::uint32_t>(i));
    }
  }

  std::string file_;
  std::vector<Line> lines_;
  LSystem system_;
  std::vector<std::pair<std::string, double>> defines_;
  std::uint32_t axiomOccurrence_ = 1;
  static constexpr int kMaxBodyNesting = 32;
  int bodyNesting_ = 0;
};

}  // namespace

LSystem parseLSystem(std::string_view text, const std::string& fileName) {
  return GrammarParser(text, fileName).parse();
}

LSystem loadLSystem(const std::filesystem::path& file) {
  std::optional<std::string> text = readFileBytes(file);
  if (!text) throw InputError({file.string(), 0, ""}, "cannot read the grammar file");
  return parseLSystem(*text, file.string());
}

}  // namespace eco
