#include "core/error.hpp"

namespace eco {
namespace {

std::string formatInputError(const SourceLocation& where, const std::string& message) {
  std::ostringstream text;
  text << (where.file.empty() ? "<input>" : where.file);
  if (where.line > 0) text << ":" << where.line;
  if (where.line > 0 && where.column > 0) text << ":" << where.column;
  text << ": ";
  if (!where.key.empty()) text << where.key << ": ";
  text << message;
  return text.str();
}

}  // namespace

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(formatInputError(where, message)),
      where_(std::move(where)),
      message_(message) {}

void assertionFailed(const char* expression, const char* function, const char* file, int line,
                     const std::string& detail) {
  std::ostringstream text;
  text << "assertion failed: " << expression << " in " << function << " (" << file << ":" << line
       << ")";
  if (!detail.empty()) text << ": " << detail;
  throw InternalError(text.str());
}

}  // namespace eco
