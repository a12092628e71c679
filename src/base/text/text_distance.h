#pragma once
// "Did you mean" support for error messages.
#include <string>
#include <vector>

namespace gloss {

// Levenshtein distance (insert, delete, substitute cost 1), case-sensitive.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The candidates sorted by edit distance to word, at most max_count of them.
std::vector<std::string> nearest_words(const std::string& word,
                                       const std::vector<std::string>& candidates,
                                       std::size_t max_count = 1);

// " (did you mean 'a'?)", " (did you mean 'a', 'b' or 'c'?)", or "" for no candidates.
std::string did_you_mean(const std::vector<std::string>& nearest);

}  // namespace gloss
