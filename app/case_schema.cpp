#include "app/case_schema.hpp"

#include "coupling/coupling_schema.hpp"
#include "dem/dem_schema.hpp"
#include "fem/fem_schema.hpp"
#include "io/case_error.hpp"
#include "io/io_schema.hpp"
#include "materials/material_schema.hpp"
#include "sph/sph_schema.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace grainload::app {

const std::vector<io::KeyTable>& case_schema() {
    static const std::vector<io::KeyTable> schema = [] {
        std::vector<io::KeyTable> tables;
        for (const auto floor :
             {io::io_key_tables(), materials::material_key_tables(), sph::sph_key_tables(),
              dem::dem_key_tables(), fem::fem_key_tables(), coupling::coupling_key_tables()}) {
            tables.insert(tables.end(), floor.begin(), floor.end());
        }
        return tables;
    }();
    return schema;
}

std::string key_help(const std::string& table) {
    std::string name = table;
    std::erase_if(name, [](char c) { return c == '[' || c == ']'; });
    std::ostringstream out;
    if (name.empty()) {
        out << "The tables of a case file (grainload help keys TABLE lists one's keys):\n\n";
        for (const io::KeyTable& part : case_schema()) {
            out << "  " << std::left << std::setw(26) << io::table_header(part) << ' ' << part.doc
                << '\n';
        }
        return out.str();
    }
    const auto parts = io::key_table_parts(case_schema(), name);
    if (parts.empty()) {
        throw io::CaseError("command line: no table '" + table +
                            "' in a case file; `grainload help keys` lists them");
    }
    for (const io::KeyTable* part : parts) {
        out << io::describe_key_table(*part) << '\n';
    }
    return out.str();
}

} // namespace grainload::app
