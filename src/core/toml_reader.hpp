// Reading user TOML files (species, scenarios) with errors that point at file, line and key.
// A TomlTable remembers which keys were read; finish() rejects any key nobody asked for, so
// a misspelt key is an error rather than a silently ignored setting.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/error.hpp"
#include "core/polyline.hpp"
#include "core/range.hpp"

namespace eco {

struct TomlPoint {
  double x = 0.0, y = 0.0;
  int line = 0;
};

class TomlTable {
 public:
  TomlTable(const toml::table& table, std::string file, std::string prefix);

  const std::string& file() const { return file_; }
  bool has(std::string_view key) const { return table_->contains(key); }
  bool isString(std::string_view key) const {
    const toml::node* node = table_->get(key);
    return node != nullptr && node->is_string();
  }
  bool isArray(std::string_view key) const {
    const toml::node* node = table_->get(key);
    return node != nullptr && node->is_array();
  }

  // Each getter marks the key as used. Without a fallback the key is required.
  double number(std::string_view key, std::optional<double> fallback = {}, Range range = {});
  std::int64_t integer(std::string_view key, std::optional<std::int64_t> fallback = {},
                       Range range = {});
  bool boolean(std::string_view key, std::optional<bool> fallback = {});
  std::string string(std::string_view key, std::optional<std::string> fallback = {});
  // A fixed-length array of numbers, e.g. a colour or a direction.
  std::vector<double> numbers(std::string_view key, std::size_t count,
                              std::optional<std::vector<double>> fallback = {}, Range range = {});
  // An array of one or more numbers, of any length.
  std::vector<double> numberList(std::string_view key,
                                 std::optional<std::vector<double>> fallback = {},
                                 Range range = {});
  // An array of strings (possibly empty), or `fallback` when the key is absent.
  std::vector<std::string> stringList(std::string_view key, std::vector<std::string> fallback);
  // [[x0, y0], [x1, y1], ...] with non-decreasing x and y inside `range`.
  Polyline polyline(std::string_view key, Range range = {});
  // [[x0, y0], [x1, y1], ...] of at least `minimum` finite pairs in any order (a polygon's
  // corners), each with the line it is written on.
  std::vector<TomlPoint> points(std::string_view key, std::size_t minimum);
  // The table's keys, sorted (a table of names to numbers, e.g. a mixture).
  std::vector<std::string> keys() const;
  std::optional<TomlTable> table(std::string_view key);
  std::vector<TomlTable> tables(std::string_view key);  // an array of tables ([[key]])

  // Throws InputError at the key (or at the table if the key is absent).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  SourceLocation where(std::string_view key) const;
  // Marks a key (a table) as read by another reader of the same file, so that finish()
  // accepts it.
  void leave(std::string_view key) { used_.emplace(key); }
  // Rejects keys that were never read.
  void finish() const;

 private:
  const toml::node& require(std::string_view key);
  std::string path(std::string_view key) const;
  void checkRange(std::string_view key, double value, Range range) const;

  const toml::table* table_;
  std::string file_;
  std::string prefix_;
  std::set<std::string, std::less<>> used_;
};

// A parsed TOML file that owns its tree.
class TomlDocument {
 public:
  // Missing or unreadable files and syntax errors become InputError with file and line.
  static TomlDocument load(const std::filesystem::path& file);
  static TomlDocument parse(std::string_view text, const std::string& displayName);

  TomlTable root() const { return TomlTable(*table_, file_, ""); }

 private:
  std::shared_ptr<toml::table> table_;
  std::string file_;
};

}  // namespace eco
