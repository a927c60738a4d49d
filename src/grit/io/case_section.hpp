// The key machinery of the case reader, shared by every table's reader: a Section reads one table's keys,
// checks each value (naming the key, the value and the reason when it is refused) and records what it was
// asked for, so that a key no reader asked for is reported as unknown, with the nearest valid spelling.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/core/spelling.hpp"

namespace grit::io {

/// A TOML value as the case file writes it (strings quoted), for messages.
std::string repr(const toml::node& node);

/// The value of a number node (is_number()) as a double. An integer beyond 2^53 is rounded to the nearest
/// double, as a float written with those digits would be (toml++'s value<double>() gives none for it, and
/// the fuzzed case reader found the exception that made).
inline double number_value(const toml::node& n) {
    if (const auto* i = n.as_integer()) return static_cast<double>(i->get());
    return n.as_floating_point()->get();
}

/// A check on a number; returns an empty string when the value is fine, else the reason.
using NumberCheck = std::function<std::string(double)>;

NumberCheck positive(const char* unit);
NumberCheck non_negative(const char* unit);
NumberCheck in_range(double lo, double hi);

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
    /// Whether `key` holds a string (for keys that take a number or a word).
    bool holds_text(std::string_view key) const {
        const toml::node* n = node(key);
        return n && n->is_string();
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
            throw core::InputError(fmt::format("key '{}' = {}: {}", key_path(key), repr(*n), reason));
        throw core::InputError(fmt::format("key '{}': {}", key_path(key), reason));
    }

    std::optional<double> maybe_number(std::string_view key, const NumberCheck& check = {}) const {
        const toml::node* n = take(key);
        if (!n) return std::nullopt;
        if (!n->is_number()) fail(key, "must be a number");
        const double v = number_value(*n);
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
            const double v = number_value(e);
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
            if (!e.is_number() || !std::isfinite(number_value(e)))
                fail(key, fmt::format("must be an array of finite numbers {}", unit));
            out.push_back(number_value(e));
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

/// Throws core::InputError for the first key of `table` (at `prefix`, "" for the top level) that no reading
/// asked for, naming the valid key of that table it is nearest to.
void report_unknown(const toml::table& table, const std::string& prefix, const KeyRecord& keys);

/// Applies one --set "a.b[1].c=value" override to the parsed case (the value in TOML syntax, or a bare word
/// as a string).
void apply_override(toml::table& root, const std::string& assignment);

}  // namespace grit::io
