#pragma once
// The whole case-file schema: every table every floor declares, and `grainload help keys`.

#include "io/key_spec.hpp"

#include <string>
#include <vector>

namespace grainload::app {

/// Every declared table of the case file, from io/, materials/, sph/, fem/ and coupling/.
const std::vector<io::KeyTable>& case_schema();

/// `grainload help keys`: the tables with their meanings; `grainload help keys TABLE` ("sph.body",
/// brackets allowed): that table's keys. Throws io::CaseError for a table nobody declares.
std::string key_help(const std::string& table);

} // namespace grainload::app
