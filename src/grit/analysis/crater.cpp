// Crater analysis.
#include "grit/analysis/crater.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grit::analysis {

namespace {
constexpr double bin_margin = 0.25;  // [spacings]
}  // namespace

CraterProfile analyse_crater(const particles::SphParticles<2>& ps, const CraterRegion& region, double spacing) {
    CraterProfile out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto bins = static_cast<std::size_t>(std::max(1.0, std::ceil((region.x_max - region.x_min) / spacing)));
    out.x.resize(bins);
    out.surface.assign(bins, nan);
    for (std::size_t b = 0; b < bins; ++b) out.x[b] = region.x_min + (static_cast<double>(b) + 0.5) * spacing;
    const auto* x = ps.position();
    const auto* phase = ps.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    for (Index i = 0; i < ps.size(); ++i) {
        if (phase[i] != solid || ps.is_image(i)) continue;
        // A particle counts in its bin and in a neighbour bin within a quarter spacing: a column that
        // drifts a little out of its bin still gives the bin its top (docs/theory.md, "Crater profile").
        const double top = x[i][1] + 0.5 * spacing;
        for (const double at : {x[i][0], -x[i][0]}) {
            const double u = (at - region.x_min) / spacing;
            for (const double v : {u - bin_margin, u + bin_margin}) {
                if (v < 0.0 || v >= static_cast<double>(bins)) continue;
                double& s = out.surface[static_cast<std::size_t>(v)];
                if (std::isnan(s) || top > s) s = top;
            }
            if (!region.mirror) break;
        }
    }
    // Deepest point; an empty bin (all eroded) is not a depth we can measure, so it is skipped.
    std::size_t deepest = bins;
    for (std::size_t b = 0; b < bins; ++b)
        if (!std::isnan(out.surface[b]) && (deepest == bins || out.surface[b] < out.surface[deepest])) deepest = b;
    if (deepest == bins) return out;
    out.depth = std::max(0.0, region.surface - out.surface[deepest]);
    const double level = region.surface - 0.5 * spacing;
    if (out.surface[deepest] >= level) return out;
    auto crossing = [&](int dir) {
        auto b = static_cast<long>(deepest);
        while (true) {
            const long next = b + dir;
            if (next < 0 || next >= static_cast<long>(bins)) return out.x[static_cast<std::size_t>(b)];
            const double s0 = out.surface[static_cast<std::size_t>(b)];
            const double s1 = out.surface[static_cast<std::size_t>(next)];
            if (!std::isnan(s1) && s1 >= level) {
                const double f = (level - s0) / (s1 - s0);
                return out.x[static_cast<std::size_t>(b)] + f * (out.x[static_cast<std::size_t>(next)] - out.x[static_cast<std::size_t>(b)]);
            }
            b = next;
        }
    };
    out.width = crossing(+1) - crossing(-1);
    return out;
}

}  // namespace grit::analysis
