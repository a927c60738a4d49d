// Fluid particles enclosed by a solid: solid particles binned in cells of `reach`, each fluid particle's
// sides closed by the solid particles of the cells around it.
#include "grit/analysis/fluid_in_solid.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace grit::analysis {

template <int Dim>
Index count_fluid_in_solids(const particles::SphParticles<Dim>& particles, double reach,
                            const neighbors::PeriodicBox<Dim>& box) {
    using Vec = core::Vec<Dim>;
    const Index n = particles.size();
    const Vec* x = particles.position();
    const std::int32_t* phase = particles.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const auto solid = static_cast<std::int32_t>(Phase::solid);

    // Cell coordinates packed in one key; 21 bits per axis cover +-1e6 cells (a periodic axis wraps the
    // distance, not the cell: with fewer than three cells across it every cell is searched anyway).
    auto cell_of = [reach](const Vec& p) {
        std::array<std::int64_t, Dim> c{};
        for (int k = 0; k < Dim; ++k) c[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(std::floor(p[k] / reach));
        return c;
    };
    auto key_of = [](const std::array<std::int64_t, Dim>& c) {
        std::uint64_t key = 0;
        for (int k = 0; k < Dim; ++k) key = (key << 21) | (static_cast<std::uint64_t>(c[static_cast<std::size_t>(k)]) & 0x1FFFFF);
        return key;
    };
    std::unordered_map<std::uint64_t, std::vector<Index>> cells;
    bool any_solid = false;
    for (Index i = 0; i < n; ++i)
        if (phase[i] == solid) {
            cells[key_of(cell_of(x[i]))].push_back(i);
            any_solid = true;
        }
    if (!any_solid) return 0;

    const double cos_cone = std::cos(enclosure_cone);
    const double reach2 = reach * reach;
    bool wraps = false;
    for (int k = 0; k < Dim; ++k) wraps |= box.periodic[static_cast<std::size_t>(k)];

    Index enclosed = 0;
    for (Index a = 0; a < n; ++a) {
        if (phase[a] != fluid || particles.is_image(a)) continue;  // images of solids do enclose
        unsigned closed = 0;  // bit 2k: a solid on the +axis-k side; bit 2k+1: on the -axis-k side
        auto visit = [&](const std::vector<Index>& members) {
            for (const Index b : members) {
                Vec d = x[b] - x[a];
                if (wraps) d = box.nearest_image(d);
                const double r2 = core::norm2(d);
                if (r2 > reach2 || r2 == 0.0) continue;
                const double r = std::sqrt(r2);
                for (int k = 0; k < Dim; ++k) {
                    if (d[k] >= cos_cone * r) closed |= 1u << (2 * k);
                    if (-d[k] >= cos_cone * r) closed |= 1u << (2 * k + 1);
                }
            }
        };
        if (wraps) {
            for (const auto& [key, members] : cells) visit(members);
        } else {
            const auto c = cell_of(x[a]);
            std::array<std::int64_t, Dim> o{};
            for (int k = 0; k < Dim; ++k) o[static_cast<std::size_t>(k)] = -1;
            while (true) {  // the 3^Dim cells around a's
                std::array<std::int64_t, Dim> q{};
                for (int k = 0; k < Dim; ++k) q[static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)] + o[static_cast<std::size_t>(k)];
                if (auto it = cells.find(key_of(q)); it != cells.end()) visit(it->second);
                int k = 0;
                while (k < Dim && ++o[static_cast<std::size_t>(k)] > 1) o[static_cast<std::size_t>(k++)] = -1;
                if (k == Dim) break;
            }
        }
        if (closed == (1u << (2 * Dim)) - 1u) ++enclosed;
    }
    return enclosed;
}

template Index count_fluid_in_solids<2>(const particles::SphParticles<2>&, double, const neighbors::PeriodicBox<2>&);
template Index count_fluid_in_solids<3>(const particles::SphParticles<3>&, double, const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
