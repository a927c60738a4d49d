// The built-in material library. Each entry cites its source.
#include "grit/material/library.hpp"

#include <fmt/format.h>

#include <type_traits>
#include <variant>

namespace grit::material {

namespace {

/// The published data of one Johnson-Cook metal.
struct MetalData {
    const char* name;
    const char* description;
    double density;         ///< rho0 [kg/m^3]
    double shear_modulus;   ///< G [Pa]
    double specific_heat;   ///< c_p [J/(kg K)]
    double sound_speed;     ///< c0 of eq. (37) [m/s]
    double hugoniot_slope;  ///< S (S_a) of eq. (37) [-]
    double gruneisen_gamma; ///< Gamma0 of eq. (37) [-]
    JohnsonCookStrength strength;
    JohnsonCookFailure failure;
};

/// A ductile solid: Mie-Gruneisen EOS in the metal form of eq. (37) (S2 = S3 = a = 0), Johnson-Cook
/// strength and failure, artificial viscosity alpha = beta = 1.0 (section 2), no physical viscosity.
Material make_metal(const MetalData& d) {
    Material m;
    m.name = d.name;
    m.description = d.description;
    m.phase = Phase::solid;
    m.eos = MieGruneisenEos{d.density, d.sound_speed, d.gruneisen_gamma, 0.0, d.hugoniot_slope, 0.0, 0.0};
    m.dynamic_viscosity = 0.0;
    m.artificial_viscosity_alpha = 1.0;
    m.artificial_viscosity_beta = 1.0;
    m.solid_model = JohnsonCook{d.strength, d.failure, true};
    m.solid.shear_modulus = d.shear_modulus;
    m.solid.specific_heat = d.specific_heat;
    m.solid.taylor_quinney = 0.9;
    m.solid.adiabatic_heating = false;
    m.solid.room_temperature = d.strength.room_temperature;
    return m;
}

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

    // Ductile solids: Johnson-Cook strength (eq. 33) and failure (eq. 35), Mie-Gruneisen EOS (eq. 37).
    lib.push_back(make_metal({"OFHC_copper",
                              "OFHC copper, first seed paper Table 2 (its ref. 49, Piao et al. 2017; J-C failure "
                              "constants of Johnson & Cook 1985); c_p = 383 J/(kg K)",
                              8960.0, 46.0e9, 383.0, 3933.0, 1.5, 1.99,
                              {90.0e6, 292.0e6, 0.31, 0.025, 1.09, 1.0, 293.0, 1790.0},
                              {0.54, 4.89, -3.03, 0.014, 1.12, 1.0, 293.0, 1790.0}}));
    lib.push_back(make_metal({"Al6061_T6",
                              "Aluminium 6061-T6, first seed paper Table 2 (its ref. 18, Takaffoli & Papini 2012); "
                              "c_p = 896 J/(kg K)",
                              2800.0, 26.0e9, 896.0, 5240.0, 1.4, 1.97,
                              {335.0e6, 85.0e6, 0.11, 0.012, 1.6, 1.0, 293.0, 925.0},
                              {-0.77, 1.45, -0.47, 0.0, 1.6, 1.0, 293.0, 925.0}}));
    lib.push_back(make_metal({"Ti6Al4V",
                              "Ti-6Al-4V: J-C strength Lesuer (2000, DOT/FAA/AR-00/25), failure Kay (2003, "
                              "DOT/FAA/AR-03/57); Mie-Gruneisen c0, S, Gamma0 and G from Steinberg (1996, "
                              "UCRL-MA-106439); c_p = 526 J/(kg K); T0 = 293 K",
                              4430.0, 41.9e9, 526.0, 5130.0, 1.028, 1.23,
                              {1098.0e6, 1092.0e6, 0.93, 0.014, 1.1, 1.0, 293.0, 1878.0},
                              {-0.09, 0.25, -0.5, 0.014, 3.87, 1.0, 293.0, 1878.0}}));
    lib.push_back(make_metal({"AISI_4340",
                              "AISI 4340 steel: J-C strength Johnson & Cook (1983), failure Johnson & Cook (1985); "
                              "Mie-Gruneisen c0, S, Gamma0 from Steinberg (1996, UCRL-MA-106439); G = 77.5 GPa, c_p = 477 J/(kg K); "
                              "T0 = 293 K",
                              7830.0, 77.5e9, 477.0, 4578.0, 1.33, 1.67,
                              {792.0e6, 510.0e6, 0.26, 0.014, 1.03, 1.0, 293.0, 1793.0},
                              {0.05, 3.44, -2.12, 0.002, 0.61, 1.0, 293.0, 1793.0}}));

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
    if (m.phase != Phase::solid) return out;
    // The keys a case file's [materials.<name>] section accepts, so a block can be pasted into a case.
    out += fmt::format("  shear_modulus = {} # [Pa]\n", m.solid.shear_modulus);
    std::visit(
        [&](const auto& model) {
            using M = std::decay_t<decltype(model)>;
            out += fmt::format("  model = \"{}\"\n", M::name);
            if constexpr (std::is_same_v<M, JohnsonCook>) {
                const auto& s = model.strength;  // eq. (33)
                out += fmt::format(
                    "  yield_stress = {} # [Pa] (A)\n  hardening_modulus = {} # [Pa] (B)\n"
                    "  hardening_exponent = {} # (n)\n  strain_rate_coefficient = {} # (C)\n"
                    "  thermal_softening_exponent = {} # (m)\n  reference_strain_rate = {} # [1/s]\n"
                    "  melt_temperature = {} # [K]\n",
                    s.A, s.B, s.n, s.C, s.m, s.reference_strain_rate, s.melt_temperature);
                const auto& f = model.failure;  // eq. (35)
                out += fmt::format("  failure = {}\n  failure_d1 = {}\n  failure_d2 = {}\n  failure_d3 = {}\n"
                                   "  failure_d4 = {}\n  failure_d5 = {}\n",
                                   model.failure_enabled, f.D1, f.D2, f.D3, f.D4, f.D5);
            }
        },
        m.solid_model);
    out += fmt::format("  specific_heat = {} # [J/(kg K)]\n  taylor_quinney = {}\n  adiabatic_heating = {}\n"
                       "  room_temperature = {} # [K]\n",
                       m.solid.specific_heat, m.solid.taylor_quinney, m.solid.adiabatic_heating,
                       m.solid.room_temperature);
    return out;
}

}  // namespace grit::material
