#include "core/names.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace eco {
namespace {

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

}  // namespace

bool sameNameIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lower(x) == lower(y); });
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  // The optimal string alignment distance over the full table (names are short).
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);  // two letters swapped
    }
  return at(n, m);
}

std::optional<std::string> closestName(std::string_view name,
                                       const std::vector<std::string>& candidates) {
  const std::size_t allowed = std::max<std::size_t>(1, name.size() / 3);
  std::optional<std::string> best;
  std::size_t bestDistance = allowed + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = editDistance(name, candidate);
    if (d < bestDistance) bestDistance = d, best = candidate;
  }
  return best;
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::optional<std::string> close = closestName(name, candidates);
  return close ? ": did you mean '" + *close + "'?" : "";
}

std::string whyNotAPlainName(std::string_view name) {
  constexpr std::size_t kLongest = 64;
  if (name.empty()) return "it is empty";
  if (name.size() > kLongest) return "it is longer than 64 characters";
  auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (!isLetter(name.front())) return "it must begin with a letter";
  for (char c : name)
    if (!isLetter(c) && !(c >= '0' && c <= '9') && c != '_' && c != '-')
      return "use only letters, digits, '_' and '-' (it becomes part of file names and CSV "
             "fields)";
  return {};
}

}  // namespace eco
