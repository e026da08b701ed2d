#pragma once
/// \file
/// "Did you mean ...?" for a misspelt key or enumeration value: the closest allowed word.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cosserat::io::detail {

/// Levenshtein distance: single-character insertions, deletions and substitutions.
std::size_t EditDistance(const std::string& a, const std::string& b);

/// The candidate equal to `word` ignoring case, else the one an engineering synonym of an end
/// condition names ("fixed-free" → "cantilever", "simply-supported" → "pinned-pinned"), else the
/// closest one within edit distance 2 that is also longer than that distance (so one-letter
/// candidates do not match everything).
std::optional<std::string> ClosestMatch(const std::string& word,
                                        const std::vector<std::string>& candidates);

}  // namespace cosserat::io::detail
