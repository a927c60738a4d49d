// The built-in material library. Each entry cites its source.
#include "grit/material/library.hpp"

#include <fmt/format.h>

#include <cmath>
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
    /// Tension cut-off [Pa] (> 0; 0: none): the pressure floor -spall_strength, LS-DYNA's PC. J-C damage
    /// grows with plastic strain only, so without it a particle pulled apart with no deviatoric flow
    /// carries any tension (docs/theory.md, "Tension cut-off").
    double spall_strength = 0.0;
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
    if (d.spall_strength > 0.0) m.min_pressure = -d.spall_strength;
    return m;
}

/// The published data of one JH-2 brittle solid (first seed paper Table 3 layout).
struct BrittleData {
    const char* name;
    const char* description;
    double density;        ///< rho0 [kg/m^3]
    double shear_modulus;  ///< G [Pa]
    double k1, k2, k3;     ///< polynomial EOS, eq. (40) [Pa]
    double beta;           ///< bulking energy fraction, eq. (41) [-]
    JH2Strength strength;
    JH2Failure failure;
};

/// A brittle solid: polynomial EOS (eq. 40) with bulking (eq. 41), JH-2 strength and damage (eqs. 38-39),
/// artificial viscosity alpha = beta = 1.0 as for every solid (section 2).
Material make_brittle(const BrittleData& d) {
    Material m;
    m.name = d.name;
    m.description = d.description;
    m.phase = Phase::solid;
    const PolynomialEos eos{d.density, d.k1, d.k2, d.k3};
    m.eos = eos;
    m.artificial_viscosity_alpha = 1.0;
    m.artificial_viscosity_beta = 1.0;
    JH2 jh2{d.strength, d.failure, d.beta};
    jh2.bind_eos(eos);
    m.solid_model = jh2;
    m.solid.shear_modulus = d.shear_modulus;
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
                              "constants of Johnson & Cook 1985); c_p = 383 J/(kg K); tension cut-off 1.3 GPa, the "
                              "spall strength of pure copper in plate impact (1.2-1.5 GPa, Kanel 2010, Int. J. Fract. "
                              "163:173)",
                              8960.0, 46.0e9, 383.0, 3933.0, 1.5, 1.99,
                              {90.0e6, 292.0e6, 0.31, 0.025, 1.09, 1.0, 293.0, 1790.0},
                              {0.54, 4.89, -3.03, 0.014, 1.12, 1.0, 293.0, 1790.0}, 1.3e9}));
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

    // Brittle solids: JH-2 (eqs. 38-39), polynomial EOS with bulking (eqs. 40-41). Strength fields:
    // A, N, B, M, C, T*, sigma_fmax*, P_HEL, sigma_HEL, reference rate.
    lib.push_back(make_brittle({"red_sandstone",
                                "Red sandstone, first seed paper Table 3 (its ref. 52, Huang, Li & Lu 2021): HEL 2.5 GPa",
                                2460.0, 7.84e9, 10.45e9, 20.78e9, 22.69e9, 1.0,
                                {0.88, 0.64, 0.293, 0.64, 0.00337, 0.0103, 0.25, 1.45e9, 1.58e9, 1.0},
                                {0.05, 1.5}}));
    lib.push_back(make_brittle({"granite",
                                "Granite, first seed paper Table 3 (its ref. 53): HEL 4.5 GPa",
                                2660.0, 21.9e9, 25.7e9, -386.0e9, 12800.0e9, 1.0,
                                {1.248, 0.676, 0.68, 0.83, 0.0051, 0.0195, 0.16, 2.93e9, 2.36e9, 1.0},
                                {0.008, 0.435}}));
    lib.push_back(make_brittle({"silicon_carbide",
                                "Silicon carbide (SiC-B), Holmquist & Johnson (2002), J. Appl. Phys. 91, 5858: "
                                "HEL 14.567 GPa, T = 0.75 GPa, no strain-rate term; sigma_HEL = 1.5 (HEL - P_HEL)",
                                3215.0, 193.0e9, 204.785e9, 0.0, 0.0, 1.0,
                                {0.96, 0.65, 0.35, 1.0, 0.0, 0.75 / 5.9, 0.8, 5.9e9, 1.5 * (14.567e9 - 5.9e9), 1.0},
                                {0.48, 0.48}}));

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
            out += fmt::format("  eos = \"{}\"\n  reference_density = {} # [kg/m^3]\n", E::name, e.reference_density);
            if constexpr (!std::is_same_v<E, PolynomialEos>) out += fmt::format("  sound_speed = {} # [m/s]\n", e.sound_speed);
            if constexpr (std::is_same_v<E, TaitEos>) {
                out += fmt::format("  gamma = {}\n", e.gamma);
            } else if constexpr (std::is_same_v<E, PolynomialEos>) {
                out += fmt::format("  k1 = {} # [Pa] (sound_speed = sqrt(k1 / rho0))\n  k2 = {} # [Pa]\n  k3 = {} # [Pa]\n",
                                   e.k1, e.k2, e.k3);
            } else {
                out += fmt::format("  gruneisen_gamma = {}\n  volume_correction = {}\n  s1 = {}\n  s2 = {}\n  s3 = {}\n",
                                   e.gruneisen_gamma, e.volume_correction, e.s1, e.s2, e.s3);
            }
        },
        m.eos);
    out += fmt::format("  dynamic_viscosity = {} # [Pa s]\n", m.dynamic_viscosity);
    out += fmt::format("  artificial_viscosity_alpha = {}\n  artificial_viscosity_beta = {}\n",
                       m.artificial_viscosity_alpha, m.artificial_viscosity_beta);
    if (std::isfinite(m.min_pressure)) out += fmt::format("  min_pressure = {} # [Pa] (pressure floor)\n", m.min_pressure);
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
                                   "  failure_d4 = {}\n  failure_d5 = {}\n"
                                   "  failure_surface_triaxiality = {} # (the most eq. 35 takes on the surface)\n"
                                   "  damage_length = {} # [m] (eq. 36 averaged over it; 0: local, as the paper)\n",
                                   model.failure_enabled, f.D1, f.D2, f.D3, f.D4, f.D5, model.surface_triaxiality,
                                   model.damage_length);
            } else if constexpr (std::is_same_v<M, JH2>) {
                const auto& s = model.strength;  // eq. (38)
                out += fmt::format(
                    "  hel_pressure = {} # [Pa] (P_HEL)\n  hel_stress = {} # [Pa] (sigma_HEL)\n"
                    "  intact_coefficient = {} # (A)\n  intact_exponent = {} # (N)\n"
                    "  fractured_coefficient = {} # (B)\n  fractured_exponent = {} # (M)\n"
                    "  strain_rate_coefficient = {} # (C)\n  reference_strain_rate = {} # [1/s]\n"
                    "  tensile_strength = {} # (T* = T / P_HEL)\n  max_fractured_strength = {} # (sigma_fmax*)\n",
                    s.hel_pressure, s.hel_stress, s.A, s.N, s.B, s.M, s.C, s.reference_strain_rate,
                    s.tensile_strength, s.max_fractured_strength);
                out += fmt::format("  failure_d1 = {}\n  failure_d2 = {}\n  min_failure_strain = {}\n"
                                   "  bulking_fraction = {} # (beta of eq. 41)\n",
                                   model.failure.D1, model.failure.D2, model.failure.min_failure_strain,
                                   model.bulking_fraction);
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
