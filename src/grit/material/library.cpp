// The built-in material library. Each entry cites its source.
#include "grit/material/library.hpp"

#include <fmt/format.h>

namespace grit::material {

namespace {

std::vector<Material> make_library() {
    std::vector<Material> lib;

    Material water;
    water.name = "water";
    water.description =
        "Water, Mie-Gruneisen EOS of the first seed paper's Table 1 (Yu et al. 2024), "
        "dynamic viscosity 1.0e-3 Pa s (Table 4); artificial viscosity alpha = beta = 0.1 (section 2)";
    water.phase = Phase::fluid;
    water.eos = MieGruneisenEos{1000.0, 1480.0, 0.5, 0.0, 2.56, 1.98, 1.23};
    water.dynamic_viscosity = 1.0e-3;
    water.artificial_viscosity_alpha = 0.1;
    water.artificial_viscosity_beta = 0.1;
    lib.push_back(water);

    Material tait = water;
    tait.name = "water_tait";
    tait.description =
        "Weakly compressible water for free-surface flows: Tait EOS, gamma = 7, c0 = 1480 m/s "
        "(set numerics-friendly c0 ~ 10 v_max with sound_speed); Monaghan (1994)";
    tait.eos = TaitEos{1000.0, 1480.0, 7.0};
    lib.push_back(tait);

    return lib;
}

}  // namespace

const std::vector<Material>& library() {
    static const std::vector<Material> lib = make_library();
    return lib;
}

std::optional<Material> find_in_library(const std::string& name) {
    for (const auto& m : library())
        if (m.name == name) return m;
    return std::nullopt;
}

std::string describe(const Material& m) {
    std::string out = fmt::format("{}\n  {}\n", m.name, m.description);
    const char* phase = m.phase == Phase::fluid ? "fluid" : m.phase == Phase::solid ? "solid" : "other";
    out += fmt::format("  phase = \"{}\"\n", phase);
    std::visit(
        [&](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            out += fmt::format("  eos = \"{}\"\n  reference_density = {} # [kg/m^3]\n  sound_speed = {} # [m/s]\n",
                               E::name, e.reference_density, e.sound_speed);
            if constexpr (std::is_same_v<E, TaitEos>) {
                out += fmt::format("  gamma = {}\n", e.gamma);
            } else {
                out += fmt::format("  gruneisen_gamma = {}\n  volume_correction = {}\n  s1 = {}\n  s2 = {}\n  s3 = {}\n",
                                   e.gruneisen_gamma, e.volume_correction, e.s1, e.s2, e.s3);
            }
        },
        m.eos);
    out += fmt::format("  dynamic_viscosity = {} # [Pa s]\n", m.dynamic_viscosity);
    out += fmt::format("  artificial_viscosity_alpha = {}\n  artificial_viscosity_beta = {}\n",
                       m.artificial_viscosity_alpha, m.artificial_viscosity_beta);
    return out;
}

}  // namespace grit::material
