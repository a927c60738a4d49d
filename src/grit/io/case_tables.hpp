// Case tables that modules read themselves. A module outside the reader registers its table's key, a reader
// that validates the table through the shared key machinery (case_section.hpp) and returns the module's spec,
// and the rules across modules it owns; read_case calls them after its own tables, so that unknown keys,
// suggestions, --set and `grit check` work for them as for every other table.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grit/io/case_spec.hpp"

namespace grit::io {

class Section;  // io/case_section.hpp: what a table's reader reads through (the reader's own include)

struct CaseTable {
    /// The top-level key: a table ([key]) or an array of tables ([[key]]), as the reader reads it.
    std::string key;
    /// Reads and validates the table, given the case's top level and what the reader has read so far (the
    /// dimension, spacing, materials); called only when the case has `key`. Its spec goes to
    /// CaseSpec::module_specs[key].
    std::function<std::shared_ptr<const ModuleSpec>(const Section& top, const CaseSpec& c)> read;
    /// Rules across modules this table's module owns, checked once every table is read (may be empty):
    /// throws core::InputError naming the keys.
    std::function<void(const CaseSpec& c)> check;
};

/// Adds a table (before any case is read: a registrar object at namespace scope). Throws std::logic_error
/// for a key another module already reads; read_case throws it for a key the reader reads itself.
void register_case_table(CaseTable table);

/// The registered tables: those of grit's own modules (builtin_case_tables), then the ones registered, in
/// registration order.
const std::vector<CaseTable>& case_tables();

/// The tables grit's own modules read themselves: defined beside the module catalog (modules/catalog.cpp),
/// so that a table in the library is linked in with it (a registrar object alone in a static library is not).
std::vector<CaseTable> builtin_case_tables();

}  // namespace grit::io
