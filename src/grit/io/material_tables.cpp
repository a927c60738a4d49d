// Reading the case's materials (material_tables.hpp).
#include "grit/io/material_tables.hpp"

namespace grit::io {

namespace {
using core::InputError;
}  // namespace

material::Material read_material(const Section& s, const std::string& name) {
    material::Material m;
    if (auto base = s.maybe_text("base")) {
        auto found = material::find_in_library(*base);
        if (!found) s.fail("base", "unknown library material (see `grit materials`)");
        m = *found;
    } else if (auto found = material::find_in_library(name)) {
        m = *found;  // a table named after a library material overrides its values
    } else {
        if (!s.has("eos")) s.fail("eos", "is required for a material that has no 'base'");
        m.description = "defined in the case file";
    }
    m.name = name;
    if (auto d = s.maybe_text("description")) m.description = *d;

    const std::string current = std::visit([](const auto& e) { return std::string(e.name); }, m.eos);
    const std::string eos = s.choice("eos", current, {"tait", "mie_gruneisen", "polynomial"});
    const double rho0 = s.number_or("reference_density", material::reference_density(m.eos), positive("[kg/m^3]"));
    if (eos == "polynomial") {
        // Eq. (40): c0 = sqrt(K1 / rho0) follows from the bulk modulus, so it is not a key here.
        if (s.has("sound_speed")) s.fail("sound_speed", "is sqrt(k1 / reference_density) for eos = \"polynomial\"; set k1");
        const auto* old = std::get_if<material::PolynomialEos>(&m.eos);
        if (!old && !s.has("k1")) s.fail("k1", "is required for eos = \"polynomial\" (bulk modulus K1 [Pa])");
        const double k1 = s.number_or("k1", old ? old->k1 : 0.0, positive("[Pa]"));
        const double k2 = s.number_or("k2", old ? old->k2 : 0.0);
        const double k3 = s.number_or("k3", old ? old->k3 : 0.0);
        m.eos = material::PolynomialEos{rho0, k1, k2, k3};
    } else {
        const double c0 = s.number_or("sound_speed", material::reference_sound_speed(m.eos), positive("[m/s]"));
        if (eos == "tait") {
            material::TaitEos t{rho0, c0, 7.0};
            if (auto* old = std::get_if<material::TaitEos>(&m.eos)) t.gamma = old->gamma;
            t.gamma = s.number_or("gamma", t.gamma, positive("[-]"));
            m.eos = t;
        } else {
            material::MieGruneisenEos g{rho0, c0, 0.5, 0.0, 1.0, 0.0, 0.0};
            if (auto* old = std::get_if<material::MieGruneisenEos>(&m.eos)) {
                g = *old;
                g.reference_density = rho0;
                g.sound_speed = c0;
            }
            g.gruneisen_gamma = s.number_or("gruneisen_gamma", g.gruneisen_gamma, non_negative("[-]"));
            g.volume_correction = s.number_or("volume_correction", g.volume_correction);
            g.s1 = s.number_or("s1", g.s1);
            g.s2 = s.number_or("s2", g.s2);
            g.s3 = s.number_or("s3", g.s3);
            m.eos = g;
        }
    }
    m.dynamic_viscosity = s.number_or("dynamic_viscosity", m.dynamic_viscosity, non_negative("[Pa s]"));
    m.artificial_viscosity_alpha =
        s.number_or("artificial_viscosity_alpha", m.artificial_viscosity_alpha, non_negative("[-]"));
    m.artificial_viscosity_beta = s.number_or("artificial_viscosity_beta", m.artificial_viscosity_beta, non_negative("[-]"));
    m.min_pressure = s.number_or("min_pressure", m.min_pressure);

    // Solids: a library solid as base, or `model` set here.
    const bool was_solid = m.phase == Phase::solid;
    const std::string current_model = std::visit([](const auto& x) { return std::string(x.name); }, m.solid_model);
    if (was_solid || s.has("model") || s.has("shear_modulus")) {
        m.phase = Phase::solid;
        const std::string model = s.choice("model", current_model, {"elastic", "johnson_cook", "jh2"});
        m.solid.shear_modulus = s.number_or("shear_modulus", m.solid.shear_modulus, positive("[Pa]"));
        if (!(m.solid.shear_modulus > 0.0)) s.fail("shear_modulus", "is required for a solid [Pa]");
        m.solid.specific_heat = s.number_or("specific_heat", m.solid.specific_heat, non_negative("[J/(kg K)]"));
        m.solid.taylor_quinney = s.number_or("taylor_quinney", m.solid.taylor_quinney, in_range(0.0, 1.0));
        m.solid.adiabatic_heating = s.flag_or("adiabatic_heating", m.solid.adiabatic_heating);
        m.solid.room_temperature = s.number_or("room_temperature", m.solid.room_temperature, positive("[K]"));
        if (m.solid.adiabatic_heating && !(m.solid.specific_heat > 0.0))
            s.fail("adiabatic_heating", "needs specific_heat > 0 [J/(kg K)]");
        if (model == "elastic") {
            m.solid_model = material::ElasticSolid{};
        } else if (model == "jh2") {
            const auto* polynomial = std::get_if<material::PolynomialEos>(&m.eos);
            if (!polynomial) s.fail("model", "\"jh2\" needs eos = \"polynomial\" (eq. 40, whose K1 the bulking of eq. 41 uses)");
            material::JH2 jh2;
            if (auto* old = std::get_if<material::JH2>(&m.solid_model)) jh2 = *old;
            auto& st = jh2.strength;  // eq. (38)
            st.hel_pressure = s.number_or("hel_pressure", st.hel_pressure, positive("[Pa]"));
            st.hel_stress = s.number_or("hel_stress", st.hel_stress, positive("[Pa]"));
            st.A = s.number_or("intact_coefficient", st.A, positive("[-]"));
            st.N = s.number_or("intact_exponent", st.N, positive("[-]"));
            st.B = s.number_or("fractured_coefficient", st.B, non_negative("[-]"));
            st.M = s.number_or("fractured_exponent", st.M, positive("[-]"));
            st.C = s.number_or("strain_rate_coefficient", st.C, non_negative("[-]"));
            st.reference_strain_rate = s.number_or("reference_strain_rate", st.reference_strain_rate, positive("[1/s]"));
            st.tensile_strength = s.number_or("tensile_strength", st.tensile_strength, non_negative("[-] (T* = T / P_HEL)"));
            st.max_fractured_strength =
                s.number_or("max_fractured_strength", st.max_fractured_strength, non_negative("[-] (sigma_fmax*)"));
            auto& f = jh2.failure;  // eq. (39)
            f.D1 = s.number_or("failure_d1", f.D1, positive("[-]"));
            f.D2 = s.number_or("failure_d2", f.D2, non_negative("[-]"));
            f.min_failure_strain = s.number_or("min_failure_strain", f.min_failure_strain, positive("[-]"));
            jh2.bulking_fraction = s.number_or("bulking_fraction", jh2.bulking_fraction, in_range(0.0, 1.0));
            for (const char* key : {"hel_pressure", "hel_stress", "intact_coefficient", "failure_d1"})
                if (!std::get_if<material::JH2>(&m.solid_model) && !s.has(key))
                    s.fail(key, "is required for a JH-2 solid (first seed paper Table 3)");
            jh2.bind_eos(*polynomial);
            m.solid_model = jh2;
        } else {
            material::JohnsonCook jc;
            if (auto* old = std::get_if<material::JohnsonCook>(&m.solid_model)) jc = *old;
            auto& st = jc.strength;
            st.A = s.number_or("yield_stress", st.A, non_negative("[Pa]"));
            st.B = s.number_or("hardening_modulus", st.B, non_negative("[Pa]"));
            st.n = s.number_or("hardening_exponent", st.n, positive("[-]"));
            st.C = s.number_or("strain_rate_coefficient", st.C, non_negative("[-]"));
            st.m = s.number_or("thermal_softening_exponent", st.m, positive("[-]"));
            st.reference_strain_rate = s.number_or("reference_strain_rate", st.reference_strain_rate, positive("[1/s]"));
            st.melt_temperature = s.number_or("melt_temperature", st.melt_temperature, positive("[K]"));
            st.room_temperature = m.solid.room_temperature;
            if (!(st.melt_temperature > st.room_temperature))
                s.fail("melt_temperature", "must exceed room_temperature [K]");
            if (!(st.A > 0.0)) s.fail("yield_stress", "is required for a Johnson-Cook solid [Pa]");
            jc.failure_enabled = s.flag_or("failure", jc.failure_enabled);
            auto& f = jc.failure;
            f.D1 = s.number_or("failure_d1", f.D1);
            f.D2 = s.number_or("failure_d2", f.D2);
            f.D3 = s.number_or("failure_d3", f.D3);
            f.D4 = s.number_or("failure_d4", f.D4);
            f.D5 = s.number_or("failure_d5", f.D5);
            jc.surface_triaxiality =
                s.number_or("failure_surface_triaxiality", jc.surface_triaxiality, positive("[-]"));
            jc.damage_length = s.number_or("damage_length", jc.damage_length, non_negative("[m]"));
            f.reference_strain_rate = st.reference_strain_rate;
            f.room_temperature = st.room_temperature;
            f.melt_temperature = st.melt_temperature;
            m.solid_model = jc;
        }
    }
    return m;
}

dem::GrainMaterial read_grain_material(const Section& s, const std::string& name) {
    dem::GrainMaterial m;
    m.name = name;
    m.density = s.number("density", positive("[kg/m^3]"));
    m.youngs_modulus = s.number("youngs_modulus", positive("[Pa]"));
    m.poisson_ratio = s.number("poisson_ratio", in_range(-0.99, 0.4999));
    m.friction = s.number("friction", non_negative("[-]"));
    m.restitution = s.number("restitution", in_range(1e-6, 1.0));
    m.diameter = s.number_or("diameter", 0.0, non_negative("[m]"));
    m.wear_youngs_modulus = s.number_or("wear_youngs_modulus", 0.0, positive("[Pa]"));
    return m;
}

wear::WearMaterial read_wear_material(const Section& top, const Section& s, std::string_view key, const std::string& name) {
    const Section defined = top.section("wear_materials");
    if (!defined.has(name)) {
        if (auto m = wear::find_wear_material(name)) return *m;
        std::string known;
        for (const auto& l : wear::wear_material_library()) known += (known.empty() ? "" : ", ") + l.name;
        s.fail(key, "is neither a [wear_materials] entry of the case nor a built-in wear material (" + known + ")");
    }
    const Section d = defined.section(name);
    wear::WearMaterial m;
    if (d.has("based_on")) {
        const std::string base = d.text("based_on");
        auto b = wear::find_wear_material(base);
        if (!b) d.fail("based_on", "is not a built-in wear material (grit materials lists them)");
        m = *b;
    }
    m.name = name;
    m.density = d.number_or("density", m.density, positive("[kg/m^3]"));
    m.youngs_modulus = d.number_or("youngs_modulus", m.youngs_modulus, positive("[Pa]"));
    m.poisson_ratio = d.number_or("poisson_ratio", m.poisson_ratio, in_range(0.0, 0.4999));
    m.flow_stress = d.number_or("flow_stress", m.flow_stress, positive("[Pa]"));
    m.elastic_limit = d.number_or("elastic_limit", m.elastic_limit, positive("[Pa]"));
    m.vickers_hardness = d.number_or("vickers_hardness", m.vickers_hardness, positive("[GPa]"));
    m.finnie_k = d.number_or("finnie_k", m.finnie_k, positive("[-]"));
    m.finnie_psi = d.number_or("finnie_psi", m.finnie_psi, positive("[-]"));
    m.bitter_exponent = d.number_or("bitter_exponent", m.bitter_exponent, in_range(1.0, 4.0));
    m.bitter_roundness = d.number_or("bitter_roundness", m.bitter_roundness, in_range(1e-3, 1.0));
    m.oka_K = d.number_or("oka_K", m.oka_K, positive("[mm^3/kg]"));
    m.oka_k1 = d.number_or("oka_k1", m.oka_k1);
    m.oka_k3 = d.number_or("oka_k3", m.oka_k3);
    m.oka_reference_speed = d.number_or("oka_reference_speed", m.oka_reference_speed, positive("[m/s]"));
    m.oka_reference_diameter = d.number_or("oka_reference_diameter", m.oka_reference_diameter, positive("[m]"));
    m.liggghts_k = d.number_or("liggghts_k", m.liggghts_k, positive("[s^2/m^2]"));
    // Bitter's E_f: a number, or "oka" (derived from Oka's E90 at a calibration speed and grain size, after
    // Oka's keys above). A built-in's derived E_f follows a changed hardness or Oka constant.
    const bool given_as_word = d.holds_text("bitter_deformation_factor");
    if (given_as_word && d.text("bitter_deformation_factor") != "oka")
        d.fail("bitter_deformation_factor", "must be a number [J/m^3] or \"oka\" (derived from Oka's E90)");
    const bool from_oka =
        given_as_word || (!d.has("bitter_deformation_factor") && std::isfinite(m.bitter_calibration_speed));
    const double speed = d.number_or("bitter_calibration_speed",
                                     std::isfinite(m.bitter_calibration_speed) ? m.bitter_calibration_speed
                                                                               : wear::bitter_reference_speed,
                                     positive("[m/s]"));
    const double diameter = d.number_or("bitter_calibration_diameter",
                                        std::isfinite(m.bitter_calibration_diameter) ? m.bitter_calibration_diameter
                                                                                     : wear::bitter_reference_diameter,
                                        positive("[m]"));
    if (from_oka) {
        if (!std::isfinite(m.vickers_hardness))
            d.fail("bitter_deformation_factor", "\"oka\" derives it from Oka's E90, which needs vickers_hardness [GPa]");
        wear::derive_bitter_deformation_factor(m, speed, diameter);
    } else {
        if (d.has("bitter_calibration_speed") || d.has("bitter_calibration_diameter"))
            d.fail(d.has("bitter_calibration_speed") ? "bitter_calibration_speed" : "bitter_calibration_diameter",
                   "applies only with bitter_deformation_factor = \"oka\"");
        m.bitter_deformation_factor = d.number_or("bitter_deformation_factor", m.bitter_deformation_factor, positive("[J/m^3]"));
        m.bitter_calibration_speed = m.bitter_calibration_diameter = NAN;
    }
    return m;
}

dem::SizeDistribution read_grain_size(const Section& s, const dem::GrainMaterial& material) {
    if (s.has("diameter") && s.has("size")) s.fail("size", "give either diameter or size, not both");
    dem::SizeDistribution out;
    if (s.has("size")) {
        const Section z = s.section("size");
        const std::string kind = z.choice("distribution", "fixed", {"fixed", "uniform", "normal", "discrete"});
        if (kind == "fixed") out = dem::FixedSize{z.number("diameter", positive("[m]"))};
        else if (kind == "discrete") out = dem::DiscreteSize{z.numbers("diameters", "[m]"), z.numbers("mass_fractions", "[-]")};
        else if (kind == "uniform") out = dem::UniformSize{z.number("min", positive("[m]")), z.number("max", positive("[m]"))};
        else out = dem::NormalSize{z.number("mean", positive("[m]")), z.number("deviation", non_negative("[m]")),
                                   z.number("min", positive("[m]")), z.number("max", positive("[m]"))};
        try {
            dem::validate(out);
        } catch (const InputError& e) {
            z.fail("distribution", e.what());
        }
    } else if (s.has("diameter")) {
        out = dem::FixedSize{s.number("diameter", positive("[m]"))};
    } else if (material.diameter > 0.0) {
        out = dem::FixedSize{material.diameter};
    } else {
        s.fail("diameter", "is required (the grain material has no nominal diameter)");
    }
    return out;
}

}  // namespace grit::io
