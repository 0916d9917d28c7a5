// Two error channels (see STYLE.md): InputError for bad user input, pointing at the file,
// line and key at fault; ECO_ASSERT for programmer mistakes, printing the offending values.
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

// A broken invariant inside ecoforest itself (exit code 1).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

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
