// Matching a name a user typed against the names there are: case-insensitively, and with a
// "did you mean" for a near miss (a typo of one or two letters).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eco {

bool sameNameIgnoringCase(std::string_view a, std::string_view b);

// The edit distance of typing: insertions, deletions, substitutions and two neighbouring
// letters swapped (Damerau's transposition, optimal string alignment), ignoring case.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `name` if it is near enough to be a typo of it: at most a
// third of its letters (and at least one) edited; ties go to the first.
std::optional<std::string> closestName(std::string_view name,
                                       const std::vector<std::string>& candidates);

// Why `name` cannot be a plain name -- one that is safe as part of a file name and as a
// CSV field: empty, longer than 64 characters, or with characters other than ASCII letters,
// digits, '_' and '-' (or not beginning with a letter). Empty when it can.
std::string whyNotAPlainName(std::string_view name);

// ": did you mean 'X'?" for a near miss, else "".
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace eco
