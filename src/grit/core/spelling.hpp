// "Did you mean ...?": the nearest of a set of valid names to a misspelt one, for input messages.
#pragma once

#include <algorithm>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grit::core {

/// Edits (insert, delete, substitute, swap two neighbours) that turn `a` into `b`: the optimal string
/// alignment distance, so the common typo of two swapped letters counts once.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    // Three rows of the dynamic-programming table: i-2, i-1 and i.
    std::vector<std::size_t> before(m + 1), previous(m + 1), current(m + 1);
    std::iota(previous.begin(), previous.end(), std::size_t{0});
    for (std::size_t i = 1; i <= n; ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t substitute = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitute});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[m];
}

/// The candidate nearest to `word`, if it is close enough to be a likely misspelling: at most one edit
/// per three letters of the longer word (and at least one). Ties go to the first candidate.
inline std::optional<std::string> closest_spelling(std::string_view word, const std::vector<std::string>& candidates) {
    std::optional<std::string> best;
    std::size_t best_distance = 0;
    for (const auto& c : candidates) {
        if (c == word) continue;
        const std::size_t d = edit_distance(word, c);
        const std::size_t allowed = std::max<std::size_t>(1, std::max(word.size(), c.size()) / 3);
        if (d <= allowed && (!best || d < best_distance)) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

}  // namespace grit::core
