// Comma-separated text (the run folder's CSV files, yield tables): reading its lines with
// their numbers, a line's fields and a field parsed whole as a number; writing a number
// with a fixed count of decimals.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/error.hpp"

namespace eco {

// Calls f(lineNumber, line) for each line of `text`, numbered from 1, without its '\n'.
template <class F>
void forEachLine(std::string_view text, F&& f) {
  int number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    f(++number, text.substr(start, end - start));
    start = end + 1;
  }
}

// Splits a line at its commas into `fields`; returns how many fields the line has (more
// than fields.size() when it has more, the surplus left unsplit).
inline std::size_t splitFields(std::string_view line, std::span<std::string_view> fields) {
  std::size_t count = 0;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    if (count == fields.size()) return count + 1;
    fields[count++] =
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    if (comma == std::string_view::npos) return count;
    start = comma + 1;
  }
}

// Parses the whole field as a number; false if it is not one, has anything after it, or is
// not finite (from_chars takes "nan" and "inf", which no file of ours holds).
template <class T>
bool parseField(std::string_view field, T& value) {
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) return false;
  return ec == std::errc() && ptr == end;
}

// Appends `value` with `decimals` digits after the point: the text of fmt's "{:.Nf}" and
// printf's "%.Nf" (rounded half to even), from the standard library's to_chars, about twice
// as fast as fmt's (a snapshot of a landscape's trees writes hundreds of millions of them).
// 64 characters hold any float (39 digits before the point) with up to 20 decimals.
inline void appendFixed(std::string& out, float value, int decimals) {
  ECO_ASSERT(decimals >= 0 && decimals <= 20, "decimals that fit the buffer");
  char text[64];
  char* end =
      std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals).ptr;
  out.append(text, end);
}

}  // namespace eco
