// The case reader's key machinery (case_section.hpp): values for messages, number checks, unknown keys and
// --set overrides.
#include "grit/io/case_section.hpp"

#include <sstream>

namespace grit::io {

namespace {
using core::InputError;
}  // namespace

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

namespace {

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

}  // namespace

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

}  // namespace grit::io
