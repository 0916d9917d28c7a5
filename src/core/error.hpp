// Three outcomes, three channels (STYLE.md): InputError for bad user input, pointing at the
// file, line and key at fault (exit code 2); EnvironmentError for a machine that cannot do
// what was asked — no display, no ffmpeg, no OpenGL 4.5, a full disk (exit code 3);
// ECO_ASSERT and InternalError for programmer mistakes, printing the offending values
// (exit code 1). The command line catches all three in one place (src/app/main.cpp).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace eco {

// Where in a user's file something is. line 0 means "the file as a whole".
struct SourceLocation {
  SourceLocation() = default;
  SourceLocation(std::string file, int line = 0, std::string key = {}, int column = 0)
      : file(std::move(file)), line(line), key(std::move(key)), column(column) {}

  std::string file;
  int line = 0;
  std::string key;  // dotted key path, e.g. "strand.local.ks_g"; may be empty
  int column = 0;   // 1-based character in the line (grammar files); 0 when not known
};

// Bad input: a missing or malformed file, an unknown key, a value out of range.
// what() reads "FILE:LINE[:COLUMN]: KEY: message"; the command line prints it and exits with
// code 2.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// The machine lacks what the work needs, or failed under it: the message says what is
// missing and how to get it; the input was fine.
class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A broken invariant inside ecoforest itself (exit code 1).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// The exit codes of the command line (README, "Exit codes").
inline constexpr int kExitBug = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitEnvironment = 3;
// `validate`: the run missed its yield table by more than the tolerance.
inline constexpr int kExitValidationFailed = 4;
inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report Ctrl-C

[[noreturn]] void assertionFailed(const char* expression, const char* function, const char* file,
                                  int line, const std::string& detail);

}  // namespace eco

// ECO_ASSERT(condition, streamed detail): ECO_ASSERT(s1 < s0, "s0=" << s0 << " s1=" << s1);
#define ECO_ASSERT(condition, detail)                                                           \
  do {                                                                                          \
    if (!(condition)) {                                                                         \
      std::ostringstream ecoAssertDetail_;                                                      \
      ecoAssertDetail_ << detail;                                                               \
      ::eco::assertionFailed(#condition, __func__, __FILE__, __LINE__, ecoAssertDetail_.str()); \
    }                                                                                           \
  } while (false)
