#include "core/toml_reader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace eco {
namespace {

int lineOf(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

TomlTable::TomlTable(const toml::table& table, std::string file, std::string prefix)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TomlTable::path(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

SourceLocation TomlTable::where(std::string_view key) const {
  for (auto&& [name, node] : *table_)
    if (name.str() == key) return {file_, static_cast<int>(name.source().begin.line), path(key)};
  return {file_, lineOf(*table_), prefix_.empty() ? std::string(key) : path(key)};
}

void TomlTable::fail(std::string_view key, const std::string& message) const {
  throw InputError(where(key), message);
}

const toml::node& TomlTable::require(std::string_view key) {
  used_.emplace(key);
  const toml::node* node = table_->get(key);
  if (node == nullptr)
    fail(key, "missing required key" +
                  (prefix_.empty() ? std::string() : " in table [" + prefix_ + "]"));
  return *node;
}

void TomlTable::checkRange(std::string_view key, double value, Range range) const {
  // TOML has inf and nan; no setting of ours takes them.
  if (!std::isfinite(value)) fail(key, "value " + formatNumber(value) + " is not a finite number");
  if (!(value >= range.min && value <= range.max))
    fail(key, "value " + formatNumber(value) + " is outside [" + formatNumber(range.min) + ", " +
                  formatNumber(range.max) + "]");
}

double TomlTable::number(std::string_view key, std::optional<double> fallback, Range range) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::node& node = require(key);
  std::optional<double> value =
      node.is_integer() ? std::optional<double>(static_cast<double>(*node.value<std::int64_t>()))
                        : node.value_exact<double>();
  if (!value) fail(key, "expected a number");
  checkRange(key, *value, range);
  return *value;
}

std::int64_t TomlTable::integer(std::string_view key, std::optional<std::int64_t> fallback,
                                Range range) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::node& node = require(key);
  if (!node.is_integer()) fail(key, "expected an integer");
  std::int64_t value = *node.value<std::int64_t>();
  checkRange(key, static_cast<double>(value), range);
  return value;
}

bool TomlTable::boolean(std::string_view key, std::optional<bool> fallback) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::node& node = require(key);
  if (!node.is_boolean()) fail(key, "expected true or false");
  return *node.value<bool>();
}

std::string TomlTable::string(std::string_view key, std::optional<std::string> fallback) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::node& node = require(key);
  if (!node.is_string()) fail(key, "expected a string");
  return *node.value<std::string>();
}

std::vector<double> TomlTable::numbers(std::string_view key, std::size_t count,
                                       std::optional<std::vector<double>> fallback, Range range) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::array* array = require(key).as_array();
  if (array == nullptr || array->size() != count)
    fail(key, "expected an array of " + std::to_string(count) + " numbers");
  return numberList(key, {}, range);
}

std::vector<double> TomlTable::numberList(std::string_view key,
                                          std::optional<std::vector<double>> fallback,
                                          Range range) {
  if (fallback && !has(key)) {
    used_.emplace(key);
    return *fallback;
  }
  const toml::node& node = require(key);
  const toml::array* array = node.as_array();
  const std::string expected =
      array != nullptr && array->size() > 0
          ? "expected an array of " + std::to_string(array->size()) + " numbers"
          : std::string("expected an array of one or more numbers");
  if (array == nullptr || array->empty()) fail(key, expected);
  std::vector<double> values;
  for (const toml::node& element : *array) {
    if (!element.is_number()) fail(key, expected);
    double value = element.is_integer() ? static_cast<double>(*element.value<std::int64_t>())
                                        : *element.value<double>();
    checkRange(key, value, range);
    values.push_back(value);
  }
  return values;
}

std::vector<std::string> TomlTable::stringList(std::string_view key,
                                               std::vector<std::string> fallback) {
  if (!has(key)) {
    used_.emplace(key);
    return fallback;
  }
  const toml::array* array = require(key).as_array();
  if (array == nullptr) fail(key, "expected an array of strings");
  std::vector<std::string> values;
  for (const toml::node& element : *array) {
    if (!element.is_string()) fail(key, "expected an array of strings");
    values.push_back(*element.value<std::string>());
  }
  return values;
}

std::vector<TomlPoint> TomlTable::points(std::string_view key, std::size_t minimum) {
  const toml::node& node = require(key);
  const toml::array* array = node.as_array();
  const std::string shape = "expected points [[x0, y0], [x1, y1], ...]";
  if (array == nullptr || array->empty()) fail(key, shape);
  std::vector<TomlPoint> points;
  for (const toml::node& element : *array) {
    const toml::array* pair = element.as_array();
    if (pair == nullptr || pair->size() != 2 || !(*pair)[0].is_number() || !(*pair)[1].is_number())
      throw InputError({file_, lineOf(element), path(key)}, shape);
    auto toDouble = [](const toml::node& n) {
      return n.is_integer() ? static_cast<double>(*n.value<std::int64_t>()) : *n.value<double>();
    };
    TomlPoint point{toDouble((*pair)[0]), toDouble((*pair)[1]), lineOf(element)};
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
      throw InputError({file_, point.line, path(key)}, "point (" + formatNumber(point.x) + ", " +
                                                           formatNumber(point.y) +
                                                           ") is not a pair of finite numbers");
    points.push_back(point);
  }
  if (points.size() < minimum)
    fail(key, "expected at least " + std::to_string(minimum) + " points, got " +
                  std::to_string(points.size()));
  return points;
}

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> names;
  for (const auto& [name, value] : *table_) names.emplace_back(name.str());
  return names;
}

Polyline TomlTable::polyline(std::string_view key, Range range) {
  std::vector<ControlPoint> points;
  for (const TomlPoint& point : this->points(key, 1)) {
    if (!points.empty() && point.x < points.back().x)
      throw InputError({file_, point.line, path(key)},
                       "control points must be sorted by abscissa: x = " + formatNumber(point.x) +
                           " comes after x = " + formatNumber(points.back().x));
    if (!(point.y >= range.min && point.y <= range.max))
      throw InputError({file_, point.line, path(key)},
                       "value " + formatNumber(point.y) + " is outside [" +
                           formatNumber(range.min) + ", " + formatNumber(range.max) + "]");
    points.push_back({point.x, point.y});
  }
  return Polyline(std::move(points));
}

std::optional<TomlTable> TomlTable::table(std::string_view key) {
  if (!has(key)) return std::nullopt;
  const toml::node& node = require(key);
  if (!node.is_table()) fail(key, "expected a table");
  return TomlTable(*node.as_table(), file_, path(key));
}

std::vector<TomlTable> TomlTable::tables(std::string_view key) {
  std::vector<TomlTable> result;
  if (!has(key)) return result;
  const toml::node& node = require(key);
  const toml::array* array = node.as_array();
  if (array == nullptr || !array->is_array_of_tables()) fail(key, "expected an array of tables");
  for (std::size_t i = 0; i < array->size(); ++i)
    result.emplace_back(*(*array)[i].as_table(), file_, path(key) + "[" + std::to_string(i) + "]");
  return result;
}

void TomlTable::finish() const {
  for (auto&& [name, node] : *table_)
    if (!used_.contains(name.str()))
      throw InputError({file_, static_cast<int>(name.source().begin.line), path(name.str())},
                       "unknown key");
}

TomlDocument TomlDocument::load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string(), 0, ""}, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), file.string());
}

TomlDocument TomlDocument::parse(std::string_view text, const std::string& displayName) {
  TomlDocument document;
  document.file_ = displayName;
  try {
    document.table_ = std::make_shared<toml::table>(toml::parse(text, displayName));
  } catch (const toml::parse_error& error) {
    throw InputError({displayName, static_cast<int>(error.source().begin.line), ""},
                     std::string(error.description()));
  }
  return document;
}

}  // namespace eco
