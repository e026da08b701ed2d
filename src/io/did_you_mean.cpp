#include "did_you_mean.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace cosserat::io::detail {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

namespace {

/// Engineering names of end conditions a user may type for ours (lower case, spaces and
/// underscores as hyphens): textbooks say "fixed" for clamped and "simply supported" for pinned.
std::optional<std::string> EndConditionSynonym(const std::string& word) {
  std::string w = Lower(word);
  std::replace(w.begin(), w.end(), '_', '-');
  std::replace(w.begin(), w.end(), ' ', '-');
  static const std::vector<std::pair<std::string, std::string>> kSynonyms = {
      {"clamped-free", "cantilever"},       {"fixed-free", "cantilever"},
      {"cantilevered", "cantilever"},       {"simply-supported", "pinned-pinned"},
      {"hinged-hinged", "pinned-pinned"},   {"fixed-fixed", "clamped-clamped"},
      {"built-in", "clamped-clamped"},      {"fixed-pinned", "clamped-pinned"},
      {"propped-cantilever", "clamped-pinned"}, {"pinned-clamped", "clamped-pinned"},
      {"free", "free-free"}};
  for (const auto& [typed, ours] : kSynonyms)
    if (w == typed) return ours;
  return std::nullopt;
}

}  // namespace

std::optional<std::string> ClosestMatch(const std::string& word,
                                        const std::vector<std::string>& candidates) {
  for (const std::string& c : candidates)
    if (Lower(c) == Lower(word)) return c;
  if (const auto ours = EndConditionSynonym(word))
    if (std::find(candidates.begin(), candidates.end(), *ours) != candidates.end()) return ours;
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  for (const std::string& c : candidates) {
    const std::size_t d = EditDistance(word, c);
    if (d < best_distance && d < c.size()) best = c, best_distance = d;
  }
  return best;
}

}  // namespace cosserat::io::detail
