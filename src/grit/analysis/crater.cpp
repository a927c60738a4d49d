// Crater analysis.
#include "grit/analysis/crater.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grit::analysis {

namespace {
constexpr double bin_margin = 0.25;  // [spacings]

/// Centres of bins one spacing wide from `lo`, enough of them to reach `hi` (at least one).
std::vector<double> bin_centres(double lo, double hi, double spacing) {
    const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil((hi - lo) / spacing)));
    std::vector<double> c(n);
    for (std::size_t b = 0; b < n; ++b) c[b] = lo + (static_cast<double>(b) + 0.5) * spacing;
    return c;
}
}  // namespace

CraterProfile analyse_crater(const particles::SphParticles<2>& ps, const CraterRegion& region, double spacing) {
    CraterProfile out = crater_bins(ps, region, spacing);
    measure_profile(out, region.surface, spacing);
    return out;
}

CraterProfile crater_bins(const particles::SphParticles<2>& ps, const CraterRegion& region, double spacing) {
    CraterProfile out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.x = bin_centres(region.x_min, region.x_max, spacing);
    const std::size_t bins = out.x.size();
    out.surface.assign(bins, nan);
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
    return out;
}

void measure_profile(CraterProfile& out, double surface0, double spacing) {
    const std::size_t bins = out.x.size();
    // Deepest point; an empty bin (all eroded) is not a depth we can measure, so it is skipped.
    std::size_t deepest = bins;
    for (std::size_t b = 0; b < bins; ++b)
        if (!std::isnan(out.surface[b]) && (deepest == bins || out.surface[b] < out.surface[deepest])) deepest = b;
    if (deepest == bins) return;
    out.depth = std::max(0.0, surface0 - out.surface[deepest]);
    const double level = surface0 - 0.5 * spacing;
    if (out.surface[deepest] >= level) return;
    struct Edge {
        double x;         // where the profile crosses the level [m]
        std::size_t bin;  // the first bin at or above it (the profile's last bin where none is)
        std::size_t last_inside;  // the last bin below the level on this side
    };
    auto crossing = [&](int dir) {
        auto b = static_cast<long>(deepest);
        while (true) {
            const long next = b + dir;
            const auto k = static_cast<std::size_t>(b);
            if (next < 0 || next >= static_cast<long>(bins)) return Edge{out.x[k], k, k};
            const double s0 = out.surface[k];
            const double s1 = out.surface[static_cast<std::size_t>(next)];
            if (!std::isnan(s1) && s1 >= level) {
                const double f = (level - s0) / (s1 - s0);
                return Edge{out.x[k] + f * (out.x[static_cast<std::size_t>(next)] - out.x[k]), static_cast<std::size_t>(next), k};
            }
            b = next;
        }
    };
    // The lip beyond an edge, looked for within half the crater's width of it: walking outwards, the
    // highest surface at least half a spacing above the original one, until the profile falls a spacing
    // below that crest (one bin's noise is half a spacing). A lip's top is often a plateau whose highest
    // bin moves with the noise, so its crest is the middle of the bins within half a spacing of the top.
    struct Lip {
        double x, height;
    };
    auto lip = [&](const Edge& edge, int dir, double reach) {
        double crest = surface0 + 0.5 * spacing;
        bool found = false;
        auto b = static_cast<long>(edge.bin);
        for (; b >= 0 && b < static_cast<long>(bins); b += dir) {
            const auto k = static_cast<std::size_t>(b);
            if (std::abs(out.x[k] - edge.x) > reach) break;
            const double s = out.surface[k];
            if (std::isnan(s)) continue;
            if (found && s < crest - spacing) break;
            if (s >= crest) {
                crest = s;
                found = true;
            }
        }
        if (!found) return Lip{edge.x, 0.0};
        double sum = 0.0;
        int n = 0;
        for (auto c = static_cast<long>(edge.bin); c != b; c += dir) {
            const auto k = static_cast<std::size_t>(c);
            if (!std::isnan(out.surface[k]) && out.surface[k] >= crest - 0.5 * spacing) {
                sum += out.x[k];
                ++n;
            }
        }
        return Lip{sum / n, crest - surface0};
    };
    const Edge left = crossing(-1), right = crossing(+1);
    out.width = right.x - left.x;
    // The section: each bin below the level counts its depth over its width; a bin with no solid left
    // (the column eroded through the region) counts at C_d, a lower bound.
    out.area = 0.0;
    for (std::size_t b = left.last_inside; b <= right.last_inside; ++b)
        out.area += spacing * (std::isnan(out.surface[b]) ? out.depth : surface0 - out.surface[b]);
    out.shape_factor = out.width > 0.0 ? out.area / (out.depth * out.width) : 0.0;
    const Lip left_lip = lip(left, -1, 0.5 * out.width), right_lip = lip(right, +1, 0.5 * out.width);
    out.rim_width = right_lip.x - left_lip.x;
    out.lip_height = 0.5 * (left_lip.height + right_lip.height);
}

CraterMap analyse_crater(const particles::SphParticles<3>& ps, const CraterRegion& region, double spacing) {
    CraterMap out = crater_bins(ps, region, spacing);
    measure_map(out, region.surface, spacing);
    return out;
}

CraterMap crater_bins(const particles::SphParticles<3>& ps, const CraterRegion& region, double spacing) {
    CraterMap out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.x = bin_centres(region.x_min, region.x_max, spacing);
    out.y = bin_centres(region.y_min, region.y_max, spacing);
    const std::size_t nx = out.x.size(), ny = out.y.size();
    out.surface.assign(nx * ny, nan);
    const auto* x = ps.position();
    const auto* phase = ps.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    for (Index i = 0; i < ps.size(); ++i) {
        if (phase[i] != solid || ps.is_image(i)) continue;
        const double top = x[i][2] + 0.5 * spacing;
        const double u = (x[i][0] - region.x_min) / spacing, w = (x[i][1] - region.y_min) / spacing;
        for (const double a : {u - bin_margin, u + bin_margin}) {
            if (a < 0.0 || a >= static_cast<double>(nx)) continue;
            for (const double b : {w - bin_margin, w + bin_margin}) {
                if (b < 0.0 || b >= static_cast<double>(ny)) continue;
                double& s = out.surface[static_cast<std::size_t>(b) * nx + static_cast<std::size_t>(a)];
                if (std::isnan(s) || top > s) s = top;
            }
        }
    }
    return out;
}

void measure_map(CraterMap& out, double surface0, double spacing) {
    const std::size_t nx = out.x.size(), ny = out.y.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::size_t deepest = out.surface.size();
    for (std::size_t k = 0; k < out.surface.size(); ++k)
        if (!std::isnan(out.surface[k]) && (deepest == out.surface.size() || out.surface[k] < out.surface[deepest]))
            deepest = k;
    if (deepest == out.surface.size()) return;
    const std::size_t di = deepest % nx;
    // Across the cut: the section through the deepest cell. Along it: the deepest cell of each x (the
    // map's lowest over y), so that pits struck at different y along the nozzle's path join.
    CraterProfile across, along;
    across.x = out.y;
    for (std::size_t j = 0; j < ny; ++j) across.surface.push_back(out.surface[j * nx + di]);
    along.x = out.x;
    along.surface.assign(nx, nan);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const double s = out.surface[j * nx + i];
            if (!std::isnan(s) && (std::isnan(along.surface[i]) || s < along.surface[i])) along.surface[i] = s;
        }
    measure_profile(across, surface0, spacing);
    measure_profile(along, surface0, spacing);
    out.depth = across.depth;
    out.width = across.width;
    out.rim_width = across.rim_width;
    out.lip_height = across.lip_height;
    out.area = across.area;
    out.shape_factor = across.shape_factor;
    out.length = along.width;
}

}  // namespace grit::analysis
