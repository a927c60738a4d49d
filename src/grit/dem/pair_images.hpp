// The periodic image of each grain pair, fixed for the life of the neighbour lists.
//
// Between two list builds no grain moves more than half the skin, and a periodic box is at least three
// cells (each wider than the list cutoff) long, so the image that is nearest for a pair at the build
// stays the nearest. The pair pass then adds the pair's shift (one of 3^Dim, looked up by a byte per pair)
// instead of rounding every component of every distance (PeriodicBox::nearest_image). The sums are the
// same to the bit: d - L * 1 and d + (-L) are one rounding of the same value, and an axis left alone adds
// -0.0, which changes no number (not even a zero's sign).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/neighbors/half_lists.hpp"
#include "grit/neighbors/periodic_box.hpp"

namespace grit::dem {

template <int Dim>
class PairImages {
public:
    using Vec = core::Vec<Dim>;
    static constexpr int codes = Dim == 2 ? 9 : 27;

    /// The codes of the pairs of `pairs` (entries of HalfLists::upper), from the positions x the lists
    /// were built at.
    void assign(const neighbors::PeriodicBox<Dim>& box, const neighbors::HalfLists& pairs, const Vec* x) {
        for (int code = 0; code < codes; ++code) {
            int rest = code;
            for (int k = 0; k < Dim; ++k) {
                const int step = rest % 3 - 1;  // -1, 0, +1 periods along axis k
                rest /= 3;
                shifts_[static_cast<std::size_t>(code)][k] = step == 0 ? -0.0 : step * box.length(k);
            }
        }
        code_.resize(pairs.upper_size());
        for_each_grain(pairs.particle_count(), [&](Index a) {
            for (Index k = pairs.upper_begin(a); k < pairs.upper_end(a); ++k) {
                const Vec d = x[pairs.upper()[k]] - x[a];
                int code = 0, place = 1;
                for (int axis = 0; axis < Dim; ++axis) {
                    // nearest_image subtracts L * round(d / L); the shift adds its negative.
                    const double periods = std::nearbyint(d[axis] * box.inverse_length(axis));
                    code += (1 - static_cast<int>(periods)) * place;
                    place *= 3;
                }
                code_[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(code);
            }
        });
    }

    const std::uint8_t* codes_per_pair() const noexcept { return code_.data(); }
    const Vec* shifts() const noexcept { return shifts_.data(); }

private:
    std::vector<std::uint8_t> code_;
    std::array<Vec, codes> shifts_{};
};

}  // namespace grit::dem
