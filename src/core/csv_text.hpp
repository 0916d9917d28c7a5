// Comma-separated text (the run folder's CSV files, yield tables): reading its lines with
// their numbers, a line's fields and a field parsed whole as a number; writing a number
// with a fixed count of decimals.
#pragma once

#include <charconv>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
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
// printf's "%.Nf" (rounded half to even; a snapshot of a landscape's trees writes hundreds
// of millions of them). Up to 12 decimals, the float scaled by 10^decimals is an exact
// double (its 24 significant bits and 5^12's 28), so rounding that to an integer, half to
// even, is printf's rounding, and the integer is printed with a point: about three times as
// fast as to_chars' fixed format, which takes the rest (64 characters hold any float, 39
// digits before the point, with up to 20 decimals).
inline void appendFixed(std::string& out, float value, int decimals) {
  ECO_ASSERT(decimals >= 0 && decimals <= 20, "decimals that fit the buffer");
  constexpr int kExactDecimals = 12;
  constexpr std::uint64_t kPowers[kExactDecimals + 1] = {
      1,        10,        100,        1000,        10000,        100000,       1000000,
      10000000, 100000000, 1000000000, 10000000000, 100000000000, 1000000000000};
  char text[64];
  char* end = text;
  const double scaled = decimals <= kExactDecimals
                            ? static_cast<double>(value) * static_cast<double>(kPowers[decimals])
                            : HUGE_VAL;
  if (std::abs(scaled) < 1e18) {  // finite, and its integer fits 64 bits
    const auto whole = static_cast<std::uint64_t>(std::abs(std::nearbyint(scaled)));
    if (std::signbit(value)) *end++ = '-';  // "-0.00" as printf writes it
    end = std::to_chars(end, text + sizeof text, whole / kPowers[decimals]).ptr;
    if (decimals > 0) {
      *end++ = '.';
      std::uint64_t fraction = whole % kPowers[decimals];
      for (int d = decimals - 1; d >= 0; --d, fraction /= 10)
        end[d] = static_cast<char>('0' + fraction % 10);
      end += decimals;
    }
  } else {
    end = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals).ptr;
  }
  out.append(text, end);
}

// Appends an integer's decimal text, as fmt's "{}" writes it, without parsing a format
// string for each of a snapshot's millions of rows.
template <std::integral T>
void appendInteger(std::string& out, T value) {
  char text[24];  // any 64-bit integer with its sign
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace eco
