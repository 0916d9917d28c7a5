// Expressions of RL-system grammars (Lluch et al., section 2): numbers, formal parameters,
// random variables, DEFINE constants, NumIt and MaxIt, C-style operators and functions.
// They compile to a little stack program: evaluating one is a loop over a few instructions,
// which keeps parametric derivation fast. TextCursor reads grammar text and reports errors
// at file:line:column.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace eco {

struct RandomVariable;

class TextCursor {
 public:
  // `text` is one line of `file`, numbered `line`; columns count from 1.
  TextCursor(std::string_view text, std::string file, int line)
      : text_(text), file_(std::move(file)), line_(line) {}

  bool atEnd() const { return pos_ >= text_.size(); }
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  char next() { return atEnd() ? '\0' : text_[pos_++]; }
  void skipSpace();
  // Skips spaces, then consumes `token` if it comes next.
  bool accept(std::string_view token);
  void expect(std::string_view token, std::string_view what);
  std::string identifier();  // letters, digits and '_', starting with a letter or '_'
  std::size_t position() const { return pos_; }
  void seek(std::size_t position) { pos_ = position; }
  int column() const { return static_cast<int>(pos_) + 1; }
  std::string_view text() const { return text_; }
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  [[noreturn]] void fail(const std::string& message) const { failAt(column(), message); }
  [[noreturn]] void failAt(int column, const std::string& message) const;

 private:
  std::string_view text_;
  std::string file_;
  int line_;
  std::size_t pos_ = 0;
};

enum class ExprOp : std::uint8_t {
  Const,
  Slot,
  Random,
  NumIt,
  MaxIt,
  Neg,
  Not,
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  And,
  Or,
  Call,
};

struct ExprInstr {
  ExprOp op = ExprOp::Const;
  std::uint8_t function = 0;     // Call: index into the function table
  std::uint16_t index = 0;       // Slot: the parameter slot; Random: the variable
  std::uint32_t occurrence = 0;  // Random: 0 in conditions, 1.. in successors
  double value = 0.0;            // Const
};

struct Expression {
  std::vector<ExprInstr> code;
  bool isConstant() const { return code.size() == 1 && code[0].op == ExprOp::Const; }
  bool usesRandom() const;
};

// What names mean while one expression is compiled.
struct ExpressionScope {
  const std::vector<std::string>* slots = nullptr;  // formal parameters; index = slot
  const std::vector<RandomVariable>* variables = nullptr;
  const std::vector<std::pair<std::string, double>>* defines = nullptr;
  // nullptr: a condition, where every variable has its matching deviate (occurrence 0).
  // Otherwise each occurrence gets the next number: a fresh deviate in successors.
  std::uint32_t* nextOccurrence = nullptr;
};

// Reads an expression, stopping before ',', ')' or "->" (or at the end of the text).
// Constant sub-results are folded; a constant expression compiles to one Const.
Expression parseExpression(TextCursor& cursor, const ExpressionScope& scope);

// Draws the deviate of (variable, occurrence) for the module being derived.
class DeviateSource {
 public:
  virtual ~DeviateSource() = default;
  virtual double deviate(int variable, std::uint32_t occurrence) const = 0;
};

struct EvalEnv {
  const double* slots = nullptr;
  double numIt = 0.0;
  double maxIt = 0.0;
  const DeviateSource* deviates = nullptr;
};

double evaluate(const Expression& expression, const EvalEnv& env);
// Conditions: true when the value is non-zero.
inline bool holds(const Expression& expression, const EvalEnv& env) {
  return evaluate(expression, env) != 0.0;
}

// The function names expressions know, for the documentation and messages.
std::string functionList();

}  // namespace eco
