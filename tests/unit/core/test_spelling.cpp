// The "did you mean" of input messages: edit distance and the nearest valid name.
#include <gtest/gtest.h>

#include "grit/core/spelling.hpp"

using grit::core::closest_spelling;
using grit::core::edit_distance;

TEST(Spelling, EditDistanceCountsEachEditOnce) {
    EXPECT_EQ(edit_distance("kernel", "kernel"), 0u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("particle_spaceing", "particle_spacing"), 1u);  // an extra letter
    EXPECT_EQ(edit_distance("particle_spacng", "particle_spacing"), 1u);    // a missing letter
    EXPECT_EQ(edit_distance("kernal", "kernel"), 1u);                       // a wrong letter
    EXPECT_EQ(edit_distance("smoothing_ratoi", "smoothing_ratio"), 1u);     // two swapped letters
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);                      // Levenshtein's example
}

TEST(Spelling, SuggestsOnlyALikelyMisspelling) {
    const std::vector<std::string> keys{"particle_spacing", "smoothing_ratio", "kernel", "density_diffusion"};
    EXPECT_EQ(closest_spelling("particle_spaceing", keys).value_or(""), "particle_spacing");
    EXPECT_EQ(closest_spelling("kernal", keys).value_or(""), "kernel");
    EXPECT_FALSE(closest_spelling("solver", keys).has_value());  // nothing near: no guess
    EXPECT_FALSE(closest_spelling("kernel", keys).has_value());  // the word itself is no suggestion
    // The nearest wins over a farther one that is also within reach.
    EXPECT_EQ(closest_spelling("outlet", {"outlets", "outlet_x"}).value_or(""), "outlets");
}
