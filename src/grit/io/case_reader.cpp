// The case reader: every key is read through a Section that remembers it, so that any key left unread
// at the end is reported as unknown (a typo must never be silently ignored).
#include "grit/io/case_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "grit/core/error.hpp"
#include "grit/core/spelling.hpp"
#include "grit/core/types.hpp"
#include "grit/io/jet_builder.hpp"
#include "grit/io/particle_budget.hpp"
#include "grit/material/library.hpp"
#include "grit/mesh/stl_file.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::io {

namespace {

using core::InputError;

std::string repr(const toml::node& node) {
    std::ostringstream os;
    if (const toml::array* a = node.as_array()) {
        os << '[';
        for (std::size_t k = 0; k < a->size(); ++k) os << (k ? ", " : "") << repr((*a)[k]);
        os << ']';
        return os.str();
    }
    node.visit([&](const auto& v) {
        if constexpr (toml::is_string<decltype(v)>)
            os << '"' << v.get() << '"';
        else if constexpr (toml::is_floating_point<decltype(v)>)
            os << fmt::format("{}", v.get());
        else
            os << v;
    });
    return os.str();
}

/// A check on a number; returns an empty string when the value is fine, else the reason.
using NumberCheck = std::function<std::string(double)>;

NumberCheck positive(const char* unit) {
    return [unit](double v) { return v > 0.0 ? std::string{} : fmt::format("must be positive {}", unit); };
}
NumberCheck non_negative(const char* unit) {
    return [unit](double v) { return v >= 0.0 ? std::string{} : fmt::format("must not be negative {}", unit); };
}
NumberCheck in_range(double lo, double hi) {
    return [lo, hi](double v) {
        return v >= lo && v <= hi ? std::string{} : fmt::format("must lie in [{}, {}]", lo, hi);
    };
}

/// The keys a reading asked for (valid keys, present or not) and the ones it found and used, as full
/// paths ("numerics.kernel", "grains[1].velocity"): what is left in the file is unknown, and the asked
/// keys of its table are what it may have meant.
struct KeyRecord {
    std::set<std::string> used;
    std::set<std::string> asked;
};

class Section {
public:
    Section(KeyRecord* keys, const toml::table* table, std::string path)
        : keys_(keys), table_(table), path_(std::move(path)) {}

    const std::string& path() const { return path_; }
    /// Whether `key` holds a table (not an array of tables).
    bool node_is_table(std::string_view key) const {
        const toml::node* n = node(key);
        return n && n->is_table();
    }
    std::string key_path(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }
    bool has(std::string_view key) const {
        keys_->asked.insert(key_path(key));
        return table_ && table_->contains(key);
    }

    [[noreturn]] void fail(std::string_view key, std::string_view reason) const {
        const toml::node* n = node(key);
        if (n)
            throw InputError(fmt::format("key '{}' = {}: {}", key_path(key), repr(*n), reason));
        throw InputError(fmt::format("key '{}': {}", key_path(key), reason));
    }

    std::optional<double> maybe_number(std::string_view key, const NumberCheck& check = {}) const {
        const toml::node* n = take(key);
        if (!n) return std::nullopt;
        if (!n->is_number()) fail(key, "must be a number");
        const double v = n->value<double>().value();
        if (!std::isfinite(v)) fail(key, "must be finite");
        if (check)
            if (auto why = check(v); !why.empty()) fail(key, why);
        return v;
    }
    double number(std::string_view key, const NumberCheck& check = {}) const {
        if (!has(key)) fail(key, required_message(key));
        return *maybe_number(key, check);
    }
    double number_or(std::string_view key, double fallback, const NumberCheck& check = {}) const {
        return maybe_number(key, check).value_or(fallback);
    }
    int integer_or(std::string_view key, int fallback, int lo, int hi) const {
        const toml::node* n = take(key);
        if (!n) return fallback;
        if (!n->is_integer()) fail(key, "must be an integer");
        const auto v = n->value<std::int64_t>().value();
        if (v < lo || v > hi) fail(key, fmt::format("must lie in [{}, {}]", lo, hi));
        return static_cast<int>(v);
    }
    std::optional<std::string> maybe_text(std::string_view key) const {
        const toml::node* n = take(key);
        if (!n) return std::nullopt;
        if (!n->is_string()) fail(key, "must be a string");
        return n->value<std::string>().value();
    }
    std::string text(std::string_view key) const {
        if (!has(key)) fail(key, required_message(key));
        return *maybe_text(key);
    }
    std::string text_or(std::string_view key, std::string fallback) const {
        return maybe_text(key).value_or(std::move(fallback));
    }
    std::string choice(std::string_view key, std::string fallback, const std::vector<std::string>& allowed) const {
        std::string v = text_or(key, fallback);
        if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
            fail(key, "must be one of " + list);
        }
        return v;
    }
    bool flag_or(std::string_view key, bool fallback) const {
        const toml::node* n = take(key);
        if (!n) return fallback;
        if (!n->is_boolean()) fail(key, "must be true or false");
        return n->value<bool>().value();
    }
    std::vector<double> vector(std::string_view key, int size, const char* unit) const {
        const toml::node* n = take(key);
        if (!n) fail(key, fmt::format("is required ({} numbers {})", size, unit));
        const toml::array* a = n->as_array();
        if (!a || static_cast<int>(a->size()) != size)
            fail(key, fmt::format("must be an array of {} numbers {} (the case is {}D)", size, unit, size));
        std::vector<double> out;
        for (const auto& e : *a) {
            if (!e.is_number()) fail(key, fmt::format("must be an array of {} numbers {}", size, unit));
            const double v = e.value<double>().value();
            if (!std::isfinite(v)) fail(key, "must hold finite numbers");
            out.push_back(v);
        }
        return out;
    }
    /// A non-empty array of finite numbers of any length.
    std::vector<double> numbers(std::string_view key, const char* unit) const {
        const toml::node* n = take(key);
        if (!n) fail(key, fmt::format("is required (an array of numbers {})", unit));
        const toml::array* a = n->as_array();
        if (!a || a->empty()) fail(key, fmt::format("must be a non-empty array of numbers {}", unit));
        std::vector<double> out;
        for (const auto& e : *a) {
            if (!e.is_number() || !std::isfinite(e.value<double>().value()))
                fail(key, fmt::format("must be an array of finite numbers {}", unit));
            out.push_back(e.value<double>().value());
        }
        return out;
    }
    std::vector<double> vector_or(std::string_view key, int size, const char* unit, std::vector<double> fallback) const {
        return has(key) ? vector(key, size, unit) : fallback;
    }
    std::vector<std::string> strings_or(std::string_view key, std::vector<std::string> fallback) const {
        const toml::node* n = take(key);
        if (!n) return fallback;
        const toml::array* a = n->as_array();
        if (!a) fail(key, "must be an array of strings");
        std::vector<std::string> out;
        for (const auto& e : *a) {
            if (!e.is_string()) fail(key, "must be an array of strings");
            out.push_back(e.value<std::string>().value());
        }
        return out;
    }
    Section section(std::string_view key) const {
        const toml::node* n = take(key);
        if (!n) return Section(keys_, nullptr, key_path(key));
        if (!n->is_table()) fail(key, "must be a table");
        return Section(keys_, n->as_table(), key_path(key));
    }
    std::vector<Section> sections(std::string_view key) const {
        std::vector<Section> out;
        const toml::node* n = take(key);
        if (!n) return out;
        const toml::array* a = n->as_array();
        if (!a) fail(key, fmt::format("must be an array of tables ([[{}]])", key));
        for (std::size_t i = 0; i < a->size(); ++i) {
            const toml::table* t = (*a)[i].as_table();
            if (!t) fail(key, fmt::format("must be an array of tables ([[{}]])", key));
            out.emplace_back(keys_, t, fmt::format("{}[{}]", key_path(key), i));
        }
        return out;
    }
    std::vector<std::string> keys() const {
        std::vector<std::string> out;
        if (table_)
            for (const auto& [k, v] : *table_) out.emplace_back(k.str());
        return out;
    }

private:
    /// "is required", and the key of this table that looks like a misspelling of it, if one does.
    std::string required_message(std::string_view key) const {
        std::vector<std::string> unread;
        if (table_)
            for (const auto& [k, v] : *table_)
                if (!keys_->used.count(key_path(k.str()))) unread.emplace_back(k.str());
        if (const auto misspelt = core::closest_spelling(key, unread))
            return fmt::format("is required (the file has '{}': did you mean '{}'?)", key_path(*misspelt), key);
        return "is required";
    }
    const toml::node* node(std::string_view key) const { return table_ ? table_->get(key) : nullptr; }
    const toml::node* take(std::string_view key) const {
        const toml::node* n = node(key);
        keys_->asked.insert(key_path(key));
        if (n) keys_->used.insert(key_path(key));
        return n;
    }

    KeyRecord* keys_;
    const toml::table* table_;
    std::string path_;
};

/// The valid keys of the table at `prefix` that the reading asked for ("" is the top level).
std::vector<std::string> asked_keys(const KeyRecord& keys, const std::string& prefix) {
    std::vector<std::string> out;
    const std::string head = prefix.empty() ? "" : prefix + ".";
    for (const auto& path : keys.asked) {
        if (path.compare(0, head.size(), head) != 0) continue;
        const std::string rest = path.substr(head.size());
        if (rest.find_first_of(".[") == std::string::npos) out.push_back(rest);
    }
    return out;
}

void report_unknown(const toml::table& table, const std::string& prefix, const KeyRecord& keys) {
    for (const auto& [k, v] : table) {
        const std::string path = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
        if (!keys.used.count(path)) {
            const auto nearest = core::closest_spelling(k.str(), asked_keys(keys, prefix));
            const std::string why = nearest ? fmt::format("did you mean '{}'?", *nearest) : "misspelt, or not valid here";
            if (v.is_table()) throw InputError(fmt::format("key '{}': unknown key (a table; {})", path, why));
            throw InputError(fmt::format("key '{}' = {}: unknown key ({})", path, repr(v), why));
        }
        if (const toml::table* t = v.as_table()) report_unknown(*t, path, keys);
        if (const toml::array* a = v.as_array())
            for (std::size_t i = 0; i < a->size(); ++i)
                if (const toml::table* t = (*a)[i].as_table()) report_unknown(*t, fmt::format("{}[{}]", path, i), keys);
    }
}

/// Applies one "a.b[1].c=value" override to the parsed table.
void apply_override(toml::table& root, const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(fmt::format("--set '{}': expected key.path=value", assignment));
    std::string path = assignment.substr(0, eq);
    std::string text = assignment.substr(eq + 1);
    auto trim = [](std::string& s) {
        s.erase(0, s.find_first_not_of(" \t"));
        s.erase(s.find_last_not_of(" \t") + 1);
    };
    trim(path);
    trim(text);

    toml::table value_holder;
    try {
        value_holder = toml::parse("v = " + text);
    } catch (const toml::parse_error&) {
        value_holder = toml::table{{"v", text}};  // a bare word is a string
    }

    std::vector<std::string> parts;
    std::stringstream ss(path);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);

    // Walks the path from table `t` at part `k`; a part naming an array of tables without an index
    // continues in every table of it (`--set fluid.solver=isph` sets the key in each [[fluid]] block).
    std::function<void(toml::table*, std::size_t)> assign = [&](toml::table* t, std::size_t first) {
        for (std::size_t k = first; k < parts.size(); ++k) {
            std::string name = parts[k];
            std::optional<std::size_t> index;
            if (auto br = name.find('['); br != std::string::npos && name.back() == ']') {
                try {
                    index = std::stoul(name.substr(br + 1, name.size() - br - 2));
                } catch (const std::exception&) {
                    throw InputError(fmt::format("--set '{}': bad index in '{}'", assignment, name));
                }
                name = name.substr(0, br);
            }
            if (name.empty()) throw InputError(fmt::format("--set '{}': empty key in the path", assignment));
            const bool last = k + 1 == parts.size();
            if (index) {
                toml::array* a = t->get_as<toml::array>(name);
                if (!a || *index >= a->size() || !(*a)[*index].is_table())
                    throw InputError(fmt::format("--set '{}': there is no table {}[{}] in the case", assignment, name, *index));
                if (last) throw InputError(fmt::format("--set '{}': cannot replace a whole table", assignment));
                t = (*a)[*index].as_table();
                continue;
            }
            if (last) {
                t->insert_or_assign(name, *value_holder.get("v"));
                // Keys that are alternatives of each other (the case gives one): setting one from the
                // command line replaces the other, so `--set jet.pressure=2e8` works on a case that gives
                // jet.velocity, and a sweep over the mass flow rate on one that gives abrasive.spacing.
                static const std::pair<const char*, const char*> alternatives[] = {
                    {"jet.velocity", "jet.pressure"}, {"abrasive.mass_flow_rate", "abrasive.spacing"}};
                for (const auto& [a, b] : alternatives) {
                    if (path == a) t->erase(std::string(b).substr(std::string(b).find('.') + 1));
                    if (path == b) t->erase(std::string(a).substr(std::string(a).find('.') + 1));
                }
            } else {
                if (toml::array* a = t->get_as<toml::array>(name); a && !a->empty() && a->is_array_of_tables()) {
                    for (auto& element : *a) assign(element.as_table(), k + 1);
                    return;
                }
                if (!t->contains(name)) t->insert(name, toml::table{});
                t = t->get_as<toml::table>(name);
                if (!t) throw InputError(fmt::format("--set '{}': '{}' is not a table", assignment, name));
            }
        }
    };
    assign(&root, 0);
}

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

class MaterialTable {
public:
    MaterialTable(const Section& defined, std::vector<material::Material>& used) : defined_(defined), used_(used) {}

    /// Index of the material named by key `key` of section `s`, which must be of phase `phase`.
    int resolve(const Section& s, std::string_view key, const std::string& name, Phase phase = Phase::fluid) {
        for (std::size_t k = 0; k < used_.size(); ++k)
            if (used_[k].name == name) return check(s, key, static_cast<int>(k), phase);
        if (defined_.has(name)) {
            used_.push_back(read_material(defined_.section(name), name));
        } else if (auto m = material::find_in_library(name)) {
            used_.push_back(*m);
        } else {
            std::string known;
            for (const auto& m2 : material::library()) known += (known.empty() ? "" : ", ") + m2.name;
            for (const auto& k : defined_.keys()) known += ", " + k;
            s.fail(key, "unknown material (known: " + known + ")");
        }
        return check(s, key, static_cast<int>(used_.size()) - 1, phase);
    }

private:
    int check(const Section& s, std::string_view key, int index, Phase phase) const {
        const Phase has = used_[static_cast<std::size_t>(index)].phase;
        if (has != phase)
            s.fail(key, phase == Phase::solid ? "is not a solid material (a solid needs shear_modulus and a model)"
                                              : "is a solid material; this block needs a fluid");
        return index;
    }

public:

private:
    const Section& defined_;
    std::vector<material::Material>& used_;
};

/// An axis-aligned box `min`/`max` (outlets, clamps).
OutletSpec read_box(const Section& s, int dim) {
    OutletSpec o;
    o.key = s.path();
    o.min = s.vector("min", dim, "[m]");
    o.max = s.vector("max", dim, "[m]");
    for (int k = 0; k < dim; ++k)
        if (o.max[k] <= o.min[k]) s.fail("max", "must exceed min in every direction");
    return o;
}

/// An STL file's triangles placed by the section's `scale`, `rotate` and `translate` (relative paths from
/// the case file's folder).
std::shared_ptr<const mesh::TriangleMesh> read_placed_mesh(const Section& s, const std::filesystem::path& folder,
                                                           bool watertight, std::filesystem::path* resolved = nullptr) {
    const std::filesystem::path file = s.text("file");
    const std::filesystem::path path = file.is_absolute() ? file : folder / file;
    if (resolved) *resolved = path;
    mesh::Placement placement;
    placement.scale = s.number_or("scale", 1.0, positive("[-]"));
    placement.rotate = core::to_vec<3>(s.vector_or("rotate", 3, "[deg]", {0.0, 0.0, 0.0}));
    placement.translate = core::to_vec<3>(s.vector_or("translate", 3, "[m]", {0.0, 0.0, 0.0}));
    return std::make_shared<const mesh::TriangleMesh>(
        mesh::TriangleMesh::from_facets(mesh::read_stl(path), placement, path.string(), watertight));
}

ShapeSpec read_shape(const Section& s, int dim, double dx, bool allow_tank, const std::filesystem::path& folder = {}) {
    ShapeSpec shape;
    std::vector<std::string> kinds = {"box", "disc", "sphere"};
    if (dim == 3) kinds.push_back("cylinder");
    if (allow_tank) kinds.push_back("tank");
    if (allow_tank && dim == 3) kinds.push_back("mesh");
    shape.kind = s.choice("shape", "box", kinds);
    if (shape.kind == "sphere") shape.kind = "disc";
    const char* axis = "xyz";
    if (shape.kind == "mesh") {
        // Wall particles are laid by the signed distance: outside/inside need a closed surface.
        shape.side = s.choice("side", "outside", {"outside", "inside", "front", "back"});
        shape.thin = s.flag_or("thin", false);
        if (shape.thin && shape.side != "front" && shape.side != "back")
            s.fail("thin", fmt::format("a thin wall has water on the side its facets face or on the other, so it needs "
                                       "side = \"front\" or \"back\", not \"{}\"", shape.side));
        shape.mesh = read_placed_mesh(s, folder, shape.side == "outside" || shape.side == "inside");
        shape.layers = s.integer_or("layers", 3, 1, 20);
    } else if (shape.kind == "box" || shape.kind == "tank") {
        shape.min = s.vector("min", dim, "[m]");
        shape.max = s.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k) {
            if (shape.max[k] <= shape.min[k])
                s.fail("max", fmt::format("must exceed min in {} ({} <= {})", axis[k], shape.max[k], shape.min[k]));
            if (shape.kind == "box" && shape.max[k] - shape.min[k] < dx)
                s.fail("max", fmt::format("the box is {} m wide in {}, less than numerics.particle_spacing = {} m "
                                          "(lengths are in metres: 0.1 mm is 1e-4)",
                                          shape.max[k] - shape.min[k], axis[k], dx));
        }
        if (shape.kind == "tank") {
            shape.layers = s.integer_or("layers", 3, 1, 20);
            shape.open = s.strings_or("open", {"top"});
            std::vector<std::string> sides = {"left", "right", "bottom", "top"};
            if (dim == 3) sides = {"left", "right", "front", "back", "bottom", "top"};
            for (const auto& o : shape.open)
                if (std::find(sides.begin(), sides.end(), o) == sides.end())
                    s.fail("open", fmt::format("unknown side \"{}\"", o));
        }
    } else if (shape.kind == "cylinder") {
        shape.center = s.vector("center", dim, "[m]");
        shape.radius = s.number("radius", positive("[m]"));
        shape.length = s.number("length", positive("[m]"));
        shape.axis = s.choice("axis", "z", {"x", "y", "z"})[0] - 'x';
        if (2.0 * shape.radius < dx || shape.length < dx)
            s.fail("radius", fmt::format("the cylinder is smaller than numerics.particle_spacing = {} m", dx));
    } else {
        shape.center = s.vector("center", dim, "[m]");
        shape.radius = s.number("radius", positive("[m]"));
        if (2.0 * shape.radius < dx)
            s.fail("radius", fmt::format("the disc is smaller than numerics.particle_spacing = {} m", dx));
    }
    return shape;
}

}  // namespace

dem::GrainMaterial read_grain_material(const Section& s, const std::string& name) {
    dem::GrainMaterial m;
    m.name = name;
    m.density = s.number("density", positive("[kg/m^3]"));
    m.youngs_modulus = s.number("youngs_modulus", positive("[Pa]"));
    m.poisson_ratio = s.number("poisson_ratio", in_range(-0.99, 0.4999));
    m.friction = s.number("friction", non_negative("[-]"));
    m.restitution = s.number("restitution", in_range(1e-6, 1.0));
    m.diameter = s.number_or("diameter", 0.0, non_negative("[m]"));
    return m;
}

namespace {

/// Grain materials by name: [grain_materials.<name>] in the case first, else the built-in library.
class GrainMaterialTable {
public:
    GrainMaterialTable(const Section& defined, std::vector<dem::GrainMaterial>& used) : defined_(defined), used_(used) {}

    int resolve(const Section& s, std::string_view key, const std::string& name) {
        for (std::size_t i = 0; i < used_.size(); ++i)
            if (used_[i].name == name) return static_cast<int>(i);
        if (defined_.has(name)) {
            used_.push_back(read_grain_material(defined_.section(name), name));
        } else if (auto m = dem::find_grain_material(name)) {
            used_.push_back(*m);
        } else {
            std::string known;
            for (const auto& l : dem::grain_material_library()) known += (known.empty() ? "" : ", ") + l.name;
            s.fail(key, "is neither a [grain_materials] entry of the case nor a built-in grain material (" + known + ")");
        }
        return static_cast<int>(used_.size()) - 1;
    }

private:
    const Section& defined_;
    std::vector<dem::GrainMaterial>& used_;
};

}  // namespace

/// A wear material: [wear_materials.<name>] (its keys on top of the built-in material `based_on`, if
/// given), else the built-in one of that name.
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
    m.bitter_deformation_factor = d.number_or("bitter_deformation_factor", m.bitter_deformation_factor, positive("[J/m^3]"));
    m.oka_K = d.number_or("oka_K", m.oka_K, positive("[mm^3/kg]"));
    m.oka_k1 = d.number_or("oka_k1", m.oka_k1);
    m.oka_k3 = d.number_or("oka_k3", m.oka_k3);
    m.oka_reference_speed = d.number_or("oka_reference_speed", m.oka_reference_speed, positive("[m/s]"));
    m.oka_reference_diameter = d.number_or("oka_reference_diameter", m.oka_reference_diameter, positive("[m]"));
    m.liggghts_k = d.number_or("liggghts_k", m.liggghts_k, positive("[s^2/m^2]"));
    return m;
}

/// [[mesh]]: STL walls for grains (3D), their placement, motion and wear model.
void read_meshes(const Section& top, CaseSpec& c, GrainMaterialTable& grain_table) {
    const auto sections = top.sections("mesh");
    if (sections.empty()) return;
    if (c.dimension != 3) throw InputError("key 'mesh': mesh walls need a 3D case (simulation.dimension = 3)");
    if (!c.has_grains()) throw InputError("key 'mesh': mesh walls act on grains for now; the case has no [[grains]] or [abrasive]");
    const std::filesystem::path folder = c.source.parent_path();
    for (const Section& m : sections) {
        MeshSpec spec;
        spec.key = m.path();
        spec.name = m.text_or("name", fmt::format("mesh{}", c.meshes.size()));
        if (spec.name.empty() || spec.name.find_first_of(", \t\"") != std::string::npos)
            m.fail("name", "must be a non-empty name without commas, spaces or quotes");
        for (const auto& other : c.meshes)
            if (other.name == spec.name) m.fail("name", "is the name of another [[mesh]]");
        spec.mesh = read_placed_mesh(m, folder, m.flag_or("watertight", false), &spec.file);
        spec.material = m.has("material") ? grain_table.resolve(m, "material", m.text("material")) : c.first_grain_material();
        const std::string model = m.choice("wear_model", "none", {"none", "finnie", "bitter", "oka", "finnie_liggghts"});
        spec.wear_model = *wear::wear_model_named(model);
        if (spec.wear_model != wear::WearModel::none) {
            const std::string material_name = m.has("wear_material") ? m.text("wear_material")
                                                                     : c.grain_materials[static_cast<std::size_t>(spec.material)].name;
            spec.wear_material = read_wear_material(top, m, m.has("wear_material") ? "wear_material" : "material", material_name);
            for (const std::string& k : wear::needed_keys(spec.wear_model)) {
                const auto& w = spec.wear_material;
                const double value = k == "density" ? w.density : k == "youngs_modulus" ? w.youngs_modulus
                                   : k == "poisson_ratio" ? w.poisson_ratio : k == "flow_stress" ? w.flow_stress
                                   : k == "elastic_limit" ? w.elastic_limit : k == "vickers_hardness" ? w.vickers_hardness
                                                                            : w.bitter_deformation_factor;
                if (!std::isfinite(value))
                    throw InputError(fmt::format("key 'wear_materials.{}.{}': needed by {}.wear_model = \"{}\"; give it "
                                                 "(or based_on = a built-in wear material)",
                                                 w.name, k, spec.key, model));
            }
        }
        spec.velocity = m.vector_or("velocity", 3, "[m/s]", {0.0, 0.0, 0.0});
        spec.angular_velocity = m.vector_or("angular_velocity", 3, "[rad/s]", {0.0, 0.0, 0.0});
        spec.centre = m.vector_or("centre", 3, "[m]", {0.0, 0.0, 0.0});
        c.meshes.push_back(std::move(spec));
    }
    // Entries no mesh uses are still checked.
    const Section defined = top.section("wear_materials");
    for (const auto& name : defined.keys()) {
        bool used = false;
        for (const auto& spec : c.meshes) used |= spec.wear_model != wear::WearModel::none && spec.wear_material.name == name;
        if (!used) read_wear_material(top, defined, name, name);
    }
}

/// Grain diameters: `diameter` (all equal) or a [..size] table with `distribution` = "fixed",
/// "uniform" (min, max) or "normal" (mean, deviation, min, max); else the material's nominal diameter.
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

/// An array of axis names ("x", "y", and "z" in 3D) as one flag per axis.
std::vector<bool> read_axes(const Section& s, std::string_view key, int dim) {
    std::vector<bool> out(static_cast<std::size_t>(dim), false);
    for (const auto& a : s.strings_or(key, {})) {
        const int k = a.size() == 1 ? a[0] - 'x' : -1;
        if (k < 0 || k >= dim) s.fail(key, fmt::format("names axes \"x\", \"y\"{}", dim == 3 ? ", \"z\"" : ""));
        out[static_cast<std::size_t>(k)] = true;
    }
    return out;
}

std::string axes_text(const std::vector<bool>& axes) {
    std::string out;
    for (std::size_t k = 0; k < axes.size(); ++k)
        if (axes[k]) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", static_cast<char>('x' + k));
    return "[" + out + "]";
}

/// domain.periodic, or dem.periodic (its older spelling): the periodic axes of the SPH particles and
/// the grains. Both given must agree. Refuses what periodic SPH does not support yet: solids, and
/// outlets that cross a periodic face.
void read_periodic(CaseSpec& c, const Section& domain, const Section& dem,
                   const std::optional<std::vector<bool>>& dem_periodic) {
    const auto dim = static_cast<std::size_t>(c.dimension);
    c.periodic.assign(dim, false);
    if (domain.has("periodic")) {
        c.periodic = read_axes(domain, "periodic", c.dimension);
        if (dem_periodic && *dem_periodic != c.periodic)
            throw InputError(fmt::format(
                "keys 'domain.periodic' = {} and 'dem.periodic' = {} differ: the periodic axes are those of the "
                "SPH particles and the grains alike; give domain.periodic only",
                axes_text(c.periodic), axes_text(*dem_periodic)));
    } else if (dem_periodic) {
        c.periodic = *dem_periodic;
        c.periodic_key = "dem.periodic";
    }
    if (!c.any_periodic()) return;
    const Section& owner = c.periodic_key == "dem.periodic" ? dem : domain;
    if (!c.solids.empty())
        owner.fail("periodic", fmt::format("periodic axes do not support solids yet ({} is a [[solid]]); remove the "
                                           "periodic axes or the solids",
                                           c.solids.front().key));
    const char* axis = "xyz";
    // The particle lattice closes across a periodic face only if the period holds whole spacings.
    if (c.has_sph())
        for (std::size_t k = 0; k < dim; ++k) {
            if (!c.periodic[k]) continue;
            const double spacings = (c.domain_max[k] - c.domain_min[k]) / c.particle_spacing;
            if (std::abs(spacings - std::round(spacings)) > 1e-6 * std::max(1.0, spacings))
                domain.fail("max", fmt::format("the period along the periodic axis {} ({} m, domain.max - domain.min) "
                                               "is {:.6g} particle spacings, not a whole number: the particle "
                                               "lattice would not close across the periodic face",
                                               axis[k], c.domain_max[k] - c.domain_min[k], spacings));
        }
    for (const auto& o : c.outlets)
        for (std::size_t k = 0; k < dim; ++k) {
            if (!c.periodic[k]) continue;
            const bool within = o.min[k] >= c.domain_min[k] && o.max[k] <= c.domain_max[k];
            const bool across = o.min[k] <= c.domain_min[k] && o.max[k] >= c.domain_max[k];
            if (!within && !across)
                throw InputError(fmt::format(
                    "key '{}.min'/'{}.max': the outlet box crosses a periodic face of the domain along {} ({} = {}); "
                    "keep it inside [domain.min, domain.max] along {} or let it span the whole period",
                    o.key, o.key, axis[k], c.periodic_key, axes_text(c.periodic), axis[k]));
        }
}

/// domain.symmetry = ["x"], or jet.symmetric: the plane x = 0 is a symmetry plane (modules/symmetry_plane).
/// Refuses what the images do not support: a periodic x axis, ISPH, mesh walls.
void read_symmetry(CaseSpec& c, const Section& domain) {
    if (domain.has("symmetry")) {
        const auto axes = read_axes(domain, "symmetry", c.dimension);
        for (std::size_t k = 1; k < axes.size(); ++k)
            if (axes[k])
                domain.fail("symmetry", "supports the plane x = 0 only ([\"x\"]): lay the set-up so that its plane "
                                        "of symmetry is x = 0");
        c.symmetry_plane = c.symmetry_plane || axes[0];
    }
    if (c.jet.symmetric) c.symmetry_key = "jet.symmetric";
    if (!c.symmetry_plane) return;
    const std::string key = c.symmetry_key;
    if (!c.periodic.empty() && c.periodic[0])
        throw InputError(fmt::format("keys '{}' and '{}' = [\"x\", ...]: the x axis cannot be periodic and mirrored "
                                     "at once", key, c.periodic_key));
    if (c.fluid_solver == "isph")
        throw InputError(fmt::format("key '{}': the symmetry plane supports fluid.solver = \"wcsph\" only", key));
    if (!c.meshes.empty() || c.has_thin_walls())
        throw InputError(fmt::format("key '{}': the symmetry plane does not mirror mesh walls ({}); lay the whole "
                                     "set-up instead", key, !c.meshes.empty() ? c.meshes.front().key : "[[wall]] thin"));
    if (!c.domain_min.empty() && c.domain_max[0] <= 0.0)
        throw InputError(fmt::format("key 'domain.max' = [{}]: with {} the domain must reach x > 0 (the half that "
                                     "is run)", fmt::join(c.domain_max, ", "), key));
    // The crater is the whole one: the profile of the half, mirrored.
    if (c.has_crater) {
        c.crater_mirror = true;
        c.crater_x_min = -c.crater_x_max;
    }
}

/// [jet]: the jet as the machine is set up. The geometry it implies is built by io/jet_builder.
void read_jet(const Section& j, CaseSpec& c, MaterialTable& table) {
    JetSpec& jet = c.jet;
    c.has_jet = true;
    jet.diameter = j.number("diameter", positive("[m]"));
    jet.material = table.resolve(j, "material", j.text_or("material", "water"));
    if (j.has("velocity") && j.has("pressure")) j.fail("pressure", "give either jet.velocity or jet.pressure, not both");
    if (j.has("pressure")) {
        // Pump pressures are hundreds of MPa; a value below 10 kPa is almost surely in MPa.
        jet.pressure = j.number("pressure", [](double v) {
            return v >= 1e4 ? std::string{}
                            : fmt::format("is in Pa and must be at least 1e4 (did you mean {} MPa = {:g} Pa?)", v, v * 1e6);
        });
        jet.volume_efficiency = j.number_or("volume_efficiency", jet.volume_efficiency, in_range(0.01, 1.0));
        const double rho = c.materials[static_cast<std::size_t>(jet.material)].reference_density();
        jet.velocity = jet_velocity_from_pressure(jet.pressure, jet.volume_efficiency, rho);
    } else {
        if (!j.has("velocity")) j.fail("velocity", "is required (or jet.pressure, the pump pressure [Pa], eq. 52)");
        jet.velocity = j.number("velocity", positive("[m/s]"));
    }
    jet.angle = j.number_or("angle", jet.angle, [](double v) {
        return v > 0.0 && v <= 90.0 ? std::string{} : std::string("must lie in (0, 90] [deg] (90: normal to the surface)");
    });
    jet.standoff = j.number("standoff", positive("[m]"));
    jet.target = j.vector_or("target", c.dimension, "[m]", {});
    jet.traverse_speed = j.number_or("traverse_speed", 0.0, non_negative("[m/s]"));
    jet.start = j.number_or("start", 0.0, non_negative("[s]"));
    jet.stop = j.number_or("stop", 1e300, non_negative("[s]"));
    if (jet.stop <= jet.start) j.fail("stop", "must come after jet.start");
    jet.side_outlets = j.flag_or("side_outlets", true);
    jet.clamp_sides = j.flag_or("clamp_sides", true);
    jet.clamp_bottom = j.flag_or("clamp_bottom", false);
    jet.symmetric = j.flag_or("symmetric", false);
}

/// [abrasive]: the grains fed into the jet; y_dis or M is completed by io/jet_builder.
void read_abrasive(const Section& a, CaseSpec& c, GrainMaterialTable& grain_table) {
    if (!c.has_jet)
        throw InputError("key 'abrasive': the abrasive feed rides a [jet]; add one, or place grains with [[grains]]");
    AbrasiveSpec& ab = c.abrasive;
    ab.enabled = true;
    ab.material = grain_table.resolve(a, "material", a.text_or("material", "garnet"));
    ab.size = read_grain_size(a, c.grain_materials[static_cast<std::size_t>(ab.material)]);
    if (a.has("mass_flow_rate") && a.has("spacing"))
        a.fail("spacing", "give either abrasive.mass_flow_rate or abrasive.spacing (y_dis), not both (eq. 55)");
    if (a.has("mass_flow_rate")) {
        ab.rate_key = "abrasive.mass_flow_rate";
        ab.mass_flow_rate = a.number("mass_flow_rate", positive("[kg/s]"));
    } else {
        if (!a.has("spacing"))
            a.fail("mass_flow_rate", "is required (or abrasive.spacing, the liquid column length y_dis of eq. 55)");
        ab.rate_key = "abrasive.spacing";
        ab.spacing = a.number("spacing", positive("[m]"));
    }
    ab.seed = static_cast<std::uint64_t>(a.integer_or("seed", 1, 0, 2147483647));
    ab.start = a.number_or("start", c.jet.start, non_negative("[s]"));
    ab.stop = a.number_or("stop", c.jet.stop, non_negative("[s]"));
    if (ab.stop <= ab.start) a.fail("stop", "must come after abrasive.start");
}

/// fluid.solver: a setting of the fluid as a whole. The fluid blocks are an array of tables
/// ([[fluid]]), so the key sits in the blocks (all that give it must agree; `--set fluid.solver=isph`
/// sets it in each), or, in a case without fluid blocks, in a [fluid] table of its own. Then [isph].
void read_fluid_solver(const Section& top, CaseSpec& c) {
    const std::vector<std::string> solvers = {"wcsph", "isph"};
    if (top.has("fluid") && top.node_is_table("fluid")) {
        // A [fluid] table (no blocks): only the fluid's settings; take it out of the way of the blocks.
        const Section f = top.section("fluid");
        c.fluid_solver = f.choice("solver", c.fluid_solver, solvers);
    } else {
        std::string first_key;
        for (const Section& f : top.sections("fluid")) {
            if (!f.has("solver")) continue;
            const std::string s = f.choice("solver", c.fluid_solver, solvers);
            if (first_key.empty()) {
                c.fluid_solver = s;
                first_key = f.key_path("solver");
            } else if (s != c.fluid_solver) {
                f.fail("solver", fmt::format("differs from {} = \"{}\": one solver integrates all the fluid",
                                             first_key, c.fluid_solver));
            }
        }
        if (!first_key.empty()) c.fluid_solver_key = first_key;
    }
    const Section isph = top.section("isph");
    if (top.has("isph") && c.fluid_solver != "isph")
        throw InputError(fmt::format("key 'isph': the settings of the incompressible solver, but {} = \"{}\"; set "
                                     "fluid.solver = \"isph\" or remove [isph]", c.fluid_solver_key, c.fluid_solver));
    c.isph.tolerance = isph.number_or("tolerance", c.isph.tolerance, in_range(1e-14, 1e-2));
    c.isph.max_iterations = isph.integer_or("max_iterations", c.isph.max_iterations, 1, 1000000);
    const double interior = c.dimension == 2 ? 2.0 : 3.0;
    c.isph.free_surface_divergence =
        isph.number_or("free_surface_divergence", c.dimension == 2 ? 1.5 : 2.4, in_range(0.1 * interior, interior));
    c.isph.density_relaxation = isph.number_or("density_relaxation", c.isph.density_relaxation, in_range(0.0, 1.0));
    c.isph.shifting = isph.number_or("shifting", c.isph.shifting, in_range(0.0, 10.0));
}

/// What the incompressible solver does not (yet) integrate: refused with the key that asked for it.
void check_fluid_solver(const CaseSpec& c) {
    if (c.fluid_solver != "isph") return;
    auto refuse = [&](const std::string& what) {
        throw InputError(fmt::format("key '{}' = \"isph\": the incompressible solver does not yet handle {}; use "
                                     "\"wcsph\" for this case",
                                     c.fluid_solver_key, what));
    };
    if (!c.solids.empty()) refuse(fmt::format("SPH solids ({})", c.solids.front().key));
    if (c.has_jet) refuse("a [jet]");
    if (!c.inlets.empty()) refuse(fmt::format("inlets ({})", c.inlets.front().key));
    if (c.fluids.empty()) refuse("a case without [[fluid]] blocks");
    if (c.shepard_interval > 0)
        throw InputError(fmt::format("key 'numerics.shepard_interval' = {}: the incompressible solver keeps every "
                                     "particle at its reference density, so there is no density to filter; set it to "
                                     "0 with {} = \"isph\"", c.shepard_interval, c.fluid_solver_key));
}

CaseSpec read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    if (!std::filesystem::exists(file)) throw InputError(fmt::format("case file '{}': no such file", file.string()));
    toml::table root;
    try {
        root = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("case file '{}' line {}: malformed TOML: {}", file.string(),
                                     e.source().begin.line, e.description()));
    }
    for (const auto& o : overrides) apply_override(root, o);

    KeyRecord keys;
    const Section top(&keys, &root, "");
    CaseSpec c;
    c.source = file;
    c.overrides = overrides;
    c.name = file.stem().string() == "case" ? file.parent_path().filename().string() : file.stem().string();
    if (c.name.empty()) c.name = "case";

    const Section sim = top.section("simulation");
    c.title = sim.text_or("title", c.name);
    c.dimension = sim.integer_or("dimension", 2, 2, 3);
    const int dim = c.dimension;

    const Section time = top.section("time");
    c.end_time = time.number("end", non_negative("[s]"));
    c.cfl = time.number_or("cfl", c.cfl, in_range(1e-3, 1.0));
    c.max_time_step = time.number_or("max_step", c.max_time_step, positive("[s]"));

    const Section output = top.section("output");
    c.output_interval = output.number("interval", positive("[s]"));
    c.write_snapshots = output.flag_or("snapshots", true);
    c.checkpoint_interval = output.number_or("checkpoint_interval", 0.0, non_negative("[s]"));
    c.checkpoint_keep = output.integer_or("checkpoint_keep", c.checkpoint_keep, 1, 1000000);
    c.checkpoint_wall_interval =
        output.number_or("checkpoint_wall_interval", c.checkpoint_wall_interval, non_negative("[s]"));
    // A time.end in the wrong unit (10 s for 10 us) would write millions of outputs: refuse it here.
    const double max_outputs = output.number_or("max_outputs", 100000.0, positive("[-]"));
    if (c.end_time / c.output_interval + 1.0 > max_outputs)
        time.fail("end", fmt::format("with output.interval = {} s the run writes {:.0f} outputs (snapshots and series "
                                     "rows), more than output.max_outputs = {:g}; raise output.interval, or "
                                     "output.max_outputs to allow it",
                                     c.output_interval, std::floor(c.end_time / c.output_interval) + 1.0, max_outputs));

    const Section numerics = top.section("numerics");
    const bool sph_blocks = top.has("fluid") || top.has("solid") || top.has("inlet") || top.has("wall");
    c.particle_spacing = sph_blocks ? numerics.number("particle_spacing", positive("[m]"))
                                    : numerics.number_or("particle_spacing", 1.0, positive("[m]"));
    c.smoothing_ratio = numerics.number_or("smoothing_ratio", c.smoothing_ratio, in_range(0.5, 3.0));
    std::vector<std::string> kernels(std::begin(sph::kernel_names), std::end(sph::kernel_names));
    c.kernel = numerics.choice("kernel", c.kernel, kernels);
    c.density_diffusion = numerics.number_or("density_diffusion", c.density_diffusion, in_range(0.0, 1.0));
    c.neighbor_skin = numerics.number_or("neighbor_skin", c.neighbor_skin, in_range(0.0, 2.0));
    c.check_interval = numerics.integer_or("check_interval", c.check_interval, 1, 1000000);
    c.max_speed = numerics.number_or("max_speed", 0.0, non_negative("[m/s]"));
    c.artificial_stress = numerics.number_or("artificial_stress", c.artificial_stress, in_range(0.0, 1.0));
    c.kernel_correction = numerics.flag_or("kernel_correction", c.kernel_correction);
    c.shepard_interval = numerics.integer_or("shepard_interval", c.shepard_interval, 0, 1000000);
    // Particle indices are 32-bit (grit::Index): no case can hold more.
    c.max_particles = numerics.integer_or("max_particles", c.max_particles, 1, std::numeric_limits<Index>::max());
    const double dx = c.particle_spacing;

    const Section physics = top.section("physics");
    c.gravity = physics.vector_or("gravity", dim, "[m/s^2]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));

    const Section materials = top.section("materials");
    MaterialTable table(materials, c.materials);

    read_fluid_solver(top, c);
    // The projection is first-order only with the corrected gradient: uncorrected, the surface
    // particles of the tank at rest sank (0.2 m/s) and its pressure was 20 % off.
    if (c.fluid_solver == "isph" && !numerics.has("kernel_correction")) c.kernel_correction = true;
    for (const Section& f : top.node_is_table("fluid") ? std::vector<Section>{} : top.sections("fluid")) {
        BlockSpec b;
        b.key = f.path();
        b.shape = read_shape(f, dim, dx, false);
        b.material = table.resolve(f, "material", f.text_or("material", "water"));
        b.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.hydrostatic = f.flag_or("hydrostatic", false);
        f.has("solver");  // read by read_fluid_solver: a known key here
        c.fluids.push_back(std::move(b));
    }
    for (const Section& s : top.sections("inlet")) {
        InletSpec in;
        in.key = s.path();
        in.position = s.vector("position", dim, "[m]");
        in.direction = s.vector("direction", dim, "[-]");
        double n2 = 0.0;
        for (double v : in.direction) n2 += v * v;
        if (n2 <= 0.0) s.fail("direction", "must not be the zero vector");
        for (double& v : in.direction) v /= std::sqrt(n2);
        in.diameter = s.number("diameter", positive("[m]"));
        if (in.diameter < dx)
            s.fail("diameter", fmt::format("is less than numerics.particle_spacing = {} m (lengths are in metres: "
                                           "0.1 mm is 1e-4)", dx));
        in.velocity = s.number("velocity", positive("[m/s]"));
        in.material = table.resolve(s, "material", s.text_or("material", "water"));
        in.start = s.number_or("start", 0.0, non_negative("[s]"));
        in.stop = s.number_or("stop", 1e300, non_negative("[s]"));
        c.inlets.push_back(std::move(in));
    }
    for (const Section& f : top.sections("solid")) {
        BlockSpec b;
        b.key = f.path();
        b.shape = read_shape(f, dim, dx, false);
        b.material = table.resolve(f, "material", f.text("material"), Phase::solid);
        b.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.velocity_profile = f.choice("velocity_profile", "uniform", {"uniform", "cantilever_mode"});
        if (b.velocity_profile == "cantilever_mode") {
            b.mode_origin = f.number("mode_origin");
            b.mode_length = f.number("mode_length", positive("[m]"));
            b.mode_tip_velocity = f.number("mode_tip_velocity");
        }
        c.solids.push_back(std::move(b));
    }
    for (const Section& s : top.sections("clamp")) {
        OutletSpec o = read_box(s, dim);
        o.velocity = s.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        c.clamps.push_back(std::move(o));
    }
    if (!c.clamps.empty() && c.solids.empty()) throw InputError("key 'clamp': clamps hold solids, and the case has no [[solid]]");
    const int default_material = !c.fluids.empty() ? c.fluids.front().material
                                 : !c.inlets.empty() ? c.inlets.front().material
                                                     : -1;
    for (const Section& w : top.sections("wall")) {
        BlockSpec b;
        b.key = w.path();
        b.shape = read_shape(w, dim, dx, true, c.source.parent_path());
        if (!w.has("material") && default_material < 0)
            w.fail("material", "is required: walls take the EOS of a fluid, and the case has none");
        b.material = w.has("material") ? table.resolve(w, "material", w.text("material")) : default_material;
        c.walls.push_back(std::move(b));
    }
    for (const Section& s : top.sections("outlet")) {
        OutletSpec o = read_box(s, dim);
        c.outlets.push_back(std::move(o));
    }
    if (top.has("jet")) read_jet(top.section("jet"), c, table);
    std::set<std::string> probe_names;
    for (const Section& s : top.sections("probe")) {
        ProbeSpec p;
        p.key = s.path();
        p.name = s.text("name");
        if (p.name.empty() || p.name.find_first_of(", \t\"") != std::string::npos)
            s.fail("name", "must be a non-empty column name without commas, spaces or quotes");
        if (!probe_names.insert(p.name).second) s.fail("name", "is used by another probe");
        p.kind = s.choice("kind", "point", {"point", "front"});
        p.phase = s.choice("phase", "fluid", {"fluid", "solid"}) == "solid" ? 1 : 0;
        if (p.kind == "point") {
            p.quantity = s.choice("quantity", "pressure", {"pressure", "density", "velocity"});
            p.position = s.vector("position", dim, "[m]");
        } else {
            const std::string axis = s.choice("axis", "x", dim == 2 ? std::vector<std::string>{"x", "y"}
                                                                    : std::vector<std::string>{"x", "y", "z"});
            p.axis = axis[0] - 'x';
            if (s.has("min") || s.has("max")) {
                p.has_region = true;
                p.min = s.vector("min", dim, "[m]");
                p.max = s.vector("max", dim, "[m]");
            }
        }
        c.probes.push_back(std::move(p));
    }

    if (top.has("crater")) {
        const Section crater = top.section("crater");
        if (c.solids.empty()) throw InputError("key 'crater': a crater needs a [[solid]]");
        c.has_crater = true;
        c.crater_surface = crater.number("surface");
        c.crater_x_min = crater.number("x_min");
        c.crater_x_max = crater.number("x_max");
        if (c.crater_x_max <= c.crater_x_min + dx) crater.fail("x_max", "must exceed x_min by more than a spacing [m]");
        if (dim == 3) {
            c.crater_y_min = crater.number("y_min");
            c.crater_y_max = crater.number("y_max");
            if (c.crater_y_max <= c.crater_y_min + dx)
                crater.fail("y_max", "must exceed y_min by more than a spacing [m]");
        }
    }

    // Crack analysis: asked for with [cracks], and on by default for brittle (JH-2) solids.
    c.crack_link_distance = 1.5 * dx;
    for (const auto& m : c.materials)
        if (std::holds_alternative<material::JH2>(m.solid_model)) c.has_cracks = true;
    if (top.has("cracks")) {
        const Section cracks = top.section("cracks");
        if (c.solids.empty()) throw InputError("key 'cracks': the crack analysis needs a [[solid]]");
        c.has_cracks = true;
        c.crack_damage_threshold = cracks.number_or("damage_threshold", c.crack_damage_threshold, in_range(1e-9, 1.0));
        c.crack_link_distance = cracks.number_or("link_distance", c.crack_link_distance, positive("[m]"));
        c.crack_min_particles = cracks.integer_or("min_particles", 3, 1, 1000000000);
    }

    const Section grain_materials = top.section("grain_materials");
    GrainMaterialTable grain_table(grain_materials, c.grain_materials);
    for (const Section& g : top.sections("grains")) {
        GrainBlockSpec b;
        b.key = g.path();
        b.material = grain_table.resolve(g, "material", g.text_or("material", "garnet"));
        b.size = read_grain_size(g, c.grain_materials[static_cast<std::size_t>(b.material)]);
        b.arrangement = g.choice("arrangement", "single", {"single", "lattice", "random"});
        if (b.arrangement == "single") {
            b.position = g.vector("position", dim, "[m]");
        } else {
            b.min = g.vector("min", dim, "[m]");
            b.max = g.vector("max", dim, "[m]");
            for (int k = 0; k < dim; ++k)
                if (b.max[k] <= b.min[k]) g.fail("max", "must exceed min in every direction");
            if (b.arrangement == "lattice") {
                b.spacing = g.number("spacing", positive("[m]"));
                b.jitter = g.number_or("jitter", 0.0, non_negative("[m]"));
            } else {
                b.count = g.integer_or("count", 0, 1, 100000000);
                if (b.count == 0) g.fail("count", "is required for arrangement = \"random\"");
            }
        }
        b.seed = static_cast<std::uint64_t>(g.integer_or("seed", 1, 0, 2147483647));
        b.velocity = g.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.fixed = g.flag_or("fixed", false);
        if (b.fixed)
            for (double v : b.velocity)
                if (v != 0.0)
                    g.fail("velocity", fmt::format("= {}: fixed grains (fixed = true) do not move; remove the velocity "
                                                   "or the fixed flag",
                                                   fmt::join(b.velocity, ", ")));
        c.grains.push_back(std::move(b));
    }
    if (top.has("abrasive")) read_abrasive(top.section("abrasive"), c, grain_table);
    for (const Section& f : top.sections("grain_feed")) {
        GrainFeedSpec feed;
        feed.key = f.path();
        feed.material = grain_table.resolve(f, "material", f.text_or("material", "garnet"));
        feed.size = read_grain_size(f, c.grain_materials[static_cast<std::size_t>(feed.material)]);
        feed.min = f.vector("min", dim, "[m]");
        feed.max = f.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k)
            if (!(feed.max[static_cast<std::size_t>(k)] > feed.min[static_cast<std::size_t>(k)]))
                f.fail("max", "must exceed min along every axis");
        feed.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        feed.mass_flow_rate = f.number("mass_flow_rate", positive("[kg/s]"));
        feed.interval = f.number("interval", positive("[s]"));
        feed.start = f.number_or("start", 0.0, non_negative("[s]"));
        feed.stop = f.number_or("stop", 1e300, positive("[s]"));
        feed.count = f.integer_or("count", 0, 0, 100'000'000);
        feed.seed = static_cast<std::uint64_t>(f.integer_or("seed", 1, 0, 2'000'000'000));
        c.grain_feeds.push_back(std::move(feed));
    }
    for (const Section& w : top.sections("grain_wall")) {
        if (!c.has_grains()) throw InputError("key 'grain_wall': grain walls need [[grains]] or [abrasive]");
        GrainWallSpec gw;
        gw.key = w.path();
        gw.name = w.text_or("name", fmt::format("plane{}", c.grain_walls.size()));
        if (gw.name.empty() || gw.name.find_first_of(", \t\"") != std::string::npos)
            w.fail("name", "must be a non-empty name without commas, spaces or quotes");
        gw.point = w.vector("point", dim, "[m]");
        gw.normal = w.vector("normal", dim, "[-]");
        double n2 = 0.0;
        for (double v : gw.normal) n2 += v * v;
        if (n2 <= 0.0) w.fail("normal", "must not be the zero vector");
        for (double& v : gw.normal) v /= std::sqrt(n2);
        gw.material = w.has("material") ? grain_table.resolve(w, "material", w.text("material")) : c.first_grain_material();
        c.grain_walls.push_back(std::move(gw));
    }
    read_meshes(top, c, grain_table);
    std::optional<std::vector<bool>> dem_periodic;
    if (top.has("dem")) {
        const Section d = top.section("dem");
        c.dem.contact_law = d.choice("contact_law", c.dem.contact_law, {"linear", "hertz"});
        c.dem.skin = d.number_or("skin", c.dem.skin, positive("[m]"));
        if (d.has("periodic")) dem_periodic = read_axes(d, "periodic", dim);
        c.dem.overlap_coefficient = d.number_or("overlap_coefficient", 0.0, in_range(0.0, 0.999));
        c.dem.solid_friction = d.number_or("solid_friction", -1.0, non_negative("[-]"));
        c.dem.wall_particle_contact = d.flag_or("wall_particle_contact", true);
        c.dem.grain_grain_contact = d.flag_or("grain_grain_contact", true);
    }
    if (top.has("coupling")) {
        const Section k = top.section("coupling");
        c.coupling.enabled = k.flag_or("enabled", true);
        // Up to 200 d: fine sand in coarse water (0.1 mm grains, 5 mm spacing) needs R_c = 2 h = 125 d.
        c.coupling.radius = k.number_or("radius", c.coupling.radius, in_range(0.5, 200.0));
        c.coupling.drag = k.choice("drag", c.coupling.drag, {"gidaspow", "di_felice", "single_particle"});
        c.coupling.min_porosity = k.number_or("min_porosity", c.coupling.min_porosity, in_range(0.01, 0.9));
    }
    for (const auto& name : grain_materials.keys()) {
        bool in_use = false;
        for (const auto& m : c.grain_materials) in_use |= m.name == name;
        if (!in_use) read_grain_material(grain_materials.section(name), name);
    }

    const Section domain = top.section("domain");
    c.jet.derive_domain = c.has_jet && !top.has("domain");
    if (!c.jet.derive_domain) {
        c.domain_min = domain.vector("min", dim, "[m]");
        c.domain_max = domain.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k)
            if (c.domain_max[k] <= c.domain_min[k]) domain.fail("max", "must exceed domain.min in every direction");
        c.remove_leaving = domain.choice("on_exit", "error", {"error", "remove"}) == "remove";
    }
    if (c.has_jet) build_jet(c);
    read_periodic(c, domain, top.section("dem"), dem_periodic);
    read_symmetry(c, domain);

    // Materials are read on first use; a defined but unused material is still checked and reported.
    for (const auto& name : materials.keys()) {
        bool in_use = false;
        for (const auto& m : c.materials) in_use |= m.name == name;
        if (!in_use) read_material(materials.section(name), name);
    }

    if (c.fluids.empty() && c.inlets.empty() && c.solids.empty() && !c.has_grains())
        throw InputError(
            "the case has nothing that moves: add a [[fluid]], [[solid]], [[inlet]], [jet], [[grains]] or [[grain_feed]]");
    check_fluid_solver(c);
    if (c.shepard_interval > 0 && c.has_grains() && c.coupling.enabled && !c.fluids.empty())
        throw InputError(fmt::format("key 'numerics.shepard_interval' = {}: the Shepard filter acts on the particle "
                                     "density, which with grains coupled to the fluid is the porosity-weighted one; "
                                     "set it to 0 or coupling.enabled = false", c.shepard_interval));
    report_unknown(root, "", keys);
    // Last, once everything else is valid: refuse a case its spacing cannot resolve, or too big to allocate.
    check_resolution(c);
    check_particle_budget(c);
    return c;
}

}  // namespace grit::io
