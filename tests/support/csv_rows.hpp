#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
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

/// discharge.csv of a run with one sink as (time, discharged mass) pairs.
inline std::vector<std::pair<double, double>> discharge_rows(const std::string& out) {
    std::ifstream in(out + "/discharge.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::pair<double, double>> rows;
    while (std::getline(in, line)) {
        std::stringstream fields(line);
        std::string time, sink, mass;
        std::getline(fields, time, ',');
        std::getline(fields, sink, ',');
        std::getline(fields, mass, ',');
        rows.emplace_back(std::stod(time), std::stod(mass));
    }
    return rows;
}

} // namespace grainload::testing
