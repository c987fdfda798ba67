#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace grainload::testing {

/// Rows of an all-numeric CSV file (coupling.csv, ...) as numbers, its header line skipped.
inline std::vector<std::vector<double>> numeric_csv_rows(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ',')) {
            row.push_back(std::stod(field));
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace grainload::testing
