#include "model/lsystem/expression.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "model/lsystem/random.hpp"

namespace eco {

void TextCursor::skipSpace() {
  while (!atEnd() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
}

bool TextCursor::accept(std::string_view token) {
  skipSpace();
  if (text_.substr(pos_, token.size()) != token) return false;
  pos_ += token.size();
  return true;
}

void TextCursor::expect(std::string_view token, std::string_view what) {
  if (accept(token)) return;
  skipSpace();
  fail("expected '" + std::string(token) + "' " + std::string(what) +
       (atEnd() ? " but the line ends" : ", found '" + std::string(1, peek()) + "'"));
}

std::string TextCursor::identifier() {
  skipSpace();
  const std::size_t start = pos_;
  auto isStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto isPart = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  if (atEnd() || !isStart(text_[pos_])) return {};
  while (!atEnd() && isPart(text_[pos_])) ++pos_;
  return std::string(text_.substr(start, pos_ - start));
}

void TextCursor::failAt(int column, const std::string& message) const {
  throw InputError({file_, line_, "", column}, message);
}

namespace {

struct Function {
  std::string_view name;
  int arity;
  double (*apply)(const double* args);
};

constexpr std::array<Function, 19> kFunctions{{
    {"sin", 1, [](const double* x) { return std::sin(x[0]); }},
    {"cos", 1, [](const double* x) { return std::cos(x[0]); }},
    {"tan", 1, [](const double* x) { return std::tan(x[0]); }},
    {"asin", 1, [](const double* x) { return std::asin(x[0]); }},
    {"acos", 1, [](const double* x) { return std::acos(x[0]); }},
    {"atan", 1, [](const double* x) { return std::atan(x[0]); }},
    {"atan2", 2, [](const double* x) { return std::atan2(x[0], x[1]); }},
    {"sqrt", 1, [](const double* x) { return std::sqrt(x[0]); }},
    {"exp", 1, [](const double* x) { return std::exp(x[0]); }},
    {"log", 1, [](const double* x) { return std::log(x[0]); }},
    {"abs", 1, [](const double* x) { return std::abs(x[0]); }},
    {"floor", 1, [](const double* x) { return std::floor(x[0]); }},
    {"ceil", 1, [](const double* x) { return std::ceil(x[0]); }},
    {"round", 1, [](const double* x) { return std::round(x[0]); }},
    {"min", 2, [](const double* x) { return std::min(x[0], x[1]); }},
    {"max", 2, [](const double* x) { return std::max(x[0], x[1]); }},
    {"pow", 2, [](const double* x) { return std::pow(x[0], x[1]); }},
    {"clamp", 3, [](const double* x) { return std::clamp(x[0], x[1], std::max(x[1], x[2])); }},
    {"sign", 1, [](const double* x) { return static_cast<double>((x[0] > 0) - (x[0] < 0)); }},
}};

constexpr int kMaxStack = 64;

class ExpressionParser {
 public:
  ExpressionParser(TextCursor& cursor, const ExpressionScope& scope)
      : cursor_(cursor), scope_(scope) {}

  Expression parse() {
    cursor_.skipSpace();
    const int start = cursor_.column();
    if (cursor_.atEnd() || cursor_.peek() == ',' || cursor_.peek() == ')')
      cursor_.fail("expected an expression");
    parseOr();
    if (depth(out_.code) > kMaxStack)
      cursor_.failAt(start, "expression nested too deeply (more than 64 pending values)");
    fold();
    return std::move(out_);
  }

 private:
  void emit(ExprOp op) { out_.code.push_back({op, 0, 0, 0, 0.0}); }

  void parseOr() {
    parseAnd();
    while (cursor_.accept("||")) {
      parseAnd();
      emit(ExprOp::Or);
    }
  }
  void parseAnd() {
    parseEquality();
    while (cursor_.accept("&&")) {
      parseEquality();
      emit(ExprOp::And);
    }
  }
  void parseEquality() {
    parseRelational();
    for (;;) {
      cursor_.skipSpace();
      if (cursor_.accept("==")) {
        parseRelational();
        emit(ExprOp::Eq);
      } else if (cursor_.accept("!=")) {
        parseRelational();
        emit(ExprOp::Ne);
      } else if (cursor_.peek() == '=') {  // Green writes NumIt = MaxIt
        cursor_.next();
        parseRelational();
        emit(ExprOp::Eq);
      } else {
        return;
      }
    }
  }
  void parseRelational() {
    parseAdditive();
    for (;;) {
      if (cursor_.accept("<=")) {
        parseAdditive();
        emit(ExprOp::Le);
      } else if (cursor_.accept(">=")) {
        parseAdditive();
        emit(ExprOp::Ge);
      } else if (cursor_.accept("<")) {
        parseAdditive();
        emit(ExprOp::Lt);
      } else if (cursor_.accept(">")) {
        parseAdditive();
        emit(ExprOp::Gt);
      } else {
        return;
      }
    }
  }
  void parseAdditive() {
    parseMultiplicative();
    for (;;) {
      cursor_.skipSpace();
      if (cursor_.peek() == '+') {
        cursor_.next();
        parseMultiplicative();
        emit(ExprOp::Add);
      } else if (cursor_.peek() == '-' && cursor_.peek(1) != '>') {  // "->" ends a condition
        cursor_.next();
        parseMultiplicative();
        emit(ExprOp::Sub);
      } else {
        return;
      }
    }
  }
  void parseMultiplicative() {
    parseUnary();
    for (;;) {
      if (cursor_.accept("*")) {
        parseUnary();
        emit(ExprOp::Mul);
      } else if (cursor_.accept("/")) {
        parseUnary();
        emit(ExprOp::Div);
      } else {
        return;
      }
    }
  }
  void parseUnary() {
    // The parser recurses for unary operators and parentheses: bound it, so a hostile
    // line cannot overflow the stack.
    if (++nesting_ > kMaxNesting) cursor_.fail("expression nested too deeply");
    parseUnaryOperand();
    --nesting_;
  }
  void parseUnaryOperand() {
    cursor_.skipSpace();
    if (cursor_.peek() == '-' && cursor_.peek(1) != '>') {
      cursor_.next();
      parseUnary();
      emit(ExprOp::Neg);
    } else if (cursor_.peek() == '!' && cursor_.peek(1) != '=') {
      cursor_.next();
      parseUnary();
      emit(ExprOp::Not);
    } else if (cursor_.peek() == '+') {
      cursor_.next();
      parseUnary();
    } else {
      parsePower();
    }
  }
  void parsePower() {
    parsePrimary();
    if (cursor_.accept("^")) {
      parseUnary();  // right-associative: 2^3^2 = 2^9; -2^2 = -4
      emit(ExprOp::Pow);
    }
  }
  void parsePrimary() {
    cursor_.skipSpace();
    const int column = cursor_.column();
    const char c = cursor_.peek();
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      parseNumber();
      return;
    }
    if (cursor_.accept("(")) {
      parseOr();
      cursor_.expect(")", "to close '('");
      return;
    }
    std::string name = cursor_.identifier();
    if (name.empty()) {
      if (cursor_.atEnd()) cursor_.fail("expected a value but the line ends");
      cursor_.fail(std::string("expected a value, found '") + c + "'");
    }
    if (cursor_.accept("(")) {
      parseCall(name, column);
      return;
    }
    resolve(name, column);
  }
  void parseNumber() {
    cursor_.skipSpace();
    const std::string_view rest = cursor_.text().substr(cursor_.position());
    double value = 0.0;
    auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
    if (error != std::errc{}) cursor_.fail("malformed number");
    cursor_.seek(cursor_.position() + static_cast<std::size_t>(end - rest.data()));
    out_.code.push_back({ExprOp::Const, 0, 0, 0, value});
  }
  void parseCall(const std::string& name, int column) {
    auto fn = std::find_if(kFunctions.begin(), kFunctions.end(),
                           [&](const Function& f) { return f.name == name; });
    if (fn == kFunctions.end())
      cursor_.failAt(column, "unknown function '" + name + "' (known: " + functionList() + ")");
    int count = 0;
    if (!cursor_.accept(")")) {
      do {
        parseOr();
        ++count;
      } while (cursor_.accept(","));
      cursor_.expect(")", "to close the arguments of " + name);
    }
    if (count != fn->arity)
      cursor_.failAt(column, name + " takes " + std::to_string(fn->arity) + " argument" +
                                 (fn->arity == 1 ? "" : "s") + ", not " + std::to_string(count));
    out_.code.push_back(
        {ExprOp::Call, static_cast<std::uint8_t>(fn - kFunctions.begin()), 0, 0, 0.0});
  }
  void resolve(const std::string& name, int column) {
    if (scope_.slots) {
      auto it = std::find(scope_.slots->begin(), scope_.slots->end(), name);
      if (it != scope_.slots->end()) {
        out_.code.push_back(
            {ExprOp::Slot, 0, static_cast<std::uint16_t>(it - scope_.slots->begin()), 0, 0.0});
        return;
      }
    }
    if (scope_.defines)
      for (const auto& [defined, value] : *scope_.defines)
        if (defined == name) {
          out_.code.push_back({ExprOp::Const, 0, 0, 0, value});
          return;
        }
    if (scope_.variables)
      for (std::size_t v = 0; v < scope_.variables->size(); ++v)
        if ((*scope_.variables)[v].name == name) {
          const std::uint32_t occurrence = scope_.nextOccurrence ? (*scope_.nextOccurrence)++ : 0;
          out_.code.push_back({ExprOp::Random, 0, static_cast<std::uint16_t>(v), occurrence, 0.0});
          return;
        }
    if (name == "NumIt") return emit(ExprOp::NumIt);
    if (name == "MaxIt") return emit(ExprOp::MaxIt);
    if (name == "pi" || name == "PI") {
      out_.code.push_back({ExprOp::Const, 0, 0, 0, std::numbers::pi});
      return;
    }
    cursor_.failAt(column, "unknown name '" + name +
                               "' (not a parameter of the predecessor, a random variable, a "
                               "DEFINE, NumIt, MaxIt or pi)");
  }

  static int depth(const std::vector<ExprInstr>& code) {
    int height = 0, most = 0;
    for (const ExprInstr& i : code) {
      switch (i.op) {
        case ExprOp::Const:
        case ExprOp::Slot:
        case ExprOp::Random:
        case ExprOp::NumIt:
        case ExprOp::MaxIt:
          ++height;
          break;
        case ExprOp::Neg:
        case ExprOp::Not:
          break;
        case ExprOp::Call:
          height -= kFunctions[i.function].arity - 1;
          break;
        default:
          --height;
      }
      most = std::max(most, height);
    }
    return most;
  }

  // An expression of constants alone is evaluated now, once.
  void fold() {
    for (const ExprInstr& i : out_.code)
      if (i.op == ExprOp::Slot || i.op == ExprOp::Random || i.op == ExprOp::NumIt ||
          i.op == ExprOp::MaxIt)
        return;
    const double value = evaluate(out_, {});
    out_.code.assign(1, {ExprOp::Const, 0, 0, 0, value});
  }

  static constexpr int kMaxNesting = 200;

  TextCursor& cursor_;
  const ExpressionScope& scope_;
  Expression out_;
  int nesting_ = 0;
};

}  // namespace

bool Expression::usesRandom() const {
  return std::any_of(code.begin(), code.end(),
                     [](const ExprInstr& i) { return i.op == ExprOp::Random; });
}

Expression parseExpression(TextCursor& cursor, const ExpressionScope& scope) {
  return ExpressionParser(cursor, scope).parse();
}

double evaluate(const Expression& expression, const EvalEnv& env) {
  if (expression.isConstant()) return expression.code[0].value;
  double stack[kMaxStack];
  int top = -1;
  for (const ExprInstr& i : expression.code) {
    switch (i.op) {
      case ExprOp::Const:
        stack[++top] = i.value;
        break;
      case ExprOp::Slot:
        stack[++top] = env.slots[i.index];
        break;
      case ExprOp::Random:
        stack[++top] = env.deviates ? env.deviates->deviate(i.index, i.occurrence) : 0.0;
        break;
      case ExprOp::NumIt:
        stack[++top] = env.numIt;
        break;
      case ExprOp::MaxIt:
        stack[++top] = env.maxIt;
        break;
      case ExprOp::Neg:
        stack[top] = -stack[top];
        break;
      case ExprOp::Not:
        stack[top] = stack[top] == 0.0 ? 1.0 : 0.0;
        break;
      case ExprOp::Call: {
        const Function& fn = kFunctions[i.function];
        top -= fn.arity - 1;
        stack[top] = fn.apply(&stack[top]);
        break;
      }
      default: {
        const double b = stack[top--];
        double& a = stack[top];
        switch (i.op) {
          case ExprOp::Add:
            a = a + b;
            break;
          case ExprOp::Sub:
            a = a - b;
            break;
          case ExprOp::Mul:
            a = a * b;
            break;
          case ExprOp::Div:
            a = a / b;
            break;
          case ExprOp::Pow:
            a = std::pow(a, b);
            break;
          case ExprOp::Lt:
            a = a < b;
            break;
          case ExprOp::Le:
            a = a <= b;
            break;
          case ExprOp::Gt:
            a = a > b;
            break;
          case ExprOp::Ge:
            a = a >= b;
            break;
          case ExprOp::Eq:
            a = a == b;
            break;
          case ExprOp::Ne:
            a = a != b;
            break;
          case ExprOp::And:
            a = (a != 0.0) && (b != 0.0);
            break;
          case ExprOp::Or:
            a = (a != 0.0) || (b != 0.0);
            break;
          default:
            break;
        }
      }
    }
  }
  return stack[top];
}

std::string functionList() {
  std::string list;
  for (const Function& f : kFunctions) {
    if (!list.empty()) list += ", ";
    list += f.name;
  }
  return list;
}

}  // namespace eco
