// The registry of module-owned case tables (case_tables.hpp).
#include "grit/io/case_tables.hpp"

#include "grit/io/case_section.hpp"

#include <algorithm>
#include <stdexcept>

namespace grit::io {

namespace {

std::vector<CaseTable>& tables() {
    static std::vector<CaseTable> registered = builtin_case_tables();
    return registered;
}

}  // namespace

void register_case_table(CaseTable table) {
    if (table.key.empty() || !table.read) throw std::logic_error("a case table needs a key and a reader");
    auto& all = tables();
    if (std::any_of(all.begin(), all.end(), [&](const CaseTable& t) { return t.key == table.key; }))
        throw std::logic_error("another module already reads the table '" + table.key + "'");
    all.push_back(std::move(table));
}

const std::vector<CaseTable>& case_tables() {
    return tables();
}

}  // namespace grit::io
