#pragma once
// The rows of a numeric CSV file a run wrote.

#include <cmath>
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

/// discharge.csv of a run as (time, discharged mass) pairs, summed over its sinks (each row
/// is one sink at one time; the sinks' rows of one time follow each other).
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
        if (!rows.empty() && rows.back().first == std::stod(time)) {
            rows.back().second += std::stod(mass);
        } else {
            rows.emplace_back(std::stod(time), std::stod(mass));
        }
    }
    return rows;
}

/// One row of wall_forces.csv: the force and moment (about the wall centre) the bodies exert
/// on a wall at an output time.
struct WallForceRow {
    double time = 0.0;
    std::string wall;
    double force[3] = {0.0, 0.0, 0.0};
    double moment[3] = {0.0, 0.0, 0.0};
};

inline std::vector<WallForceRow> wall_force_rows(const std::string& out) {
    std::ifstream in(out + "/wall_forces.csv");
    std::string line;
    std::getline(in, line);
    std::vector<WallForceRow> rows;
    while (std::getline(in, line)) {
        std::stringstream fields(line);
        std::string field;
        WallForceRow row;
        std::getline(fields, field, ',');
        row.time = std::stod(field);
        std::getline(fields, row.wall, ',');
        for (double* value : {&row.force[0], &row.force[1], &row.force[2], &row.moment[0],
                              &row.moment[1], &row.moment[2]}) {
            std::getline(fields, field, ',');
            *value = std::stod(field);
        }
        rows.push_back(row);
    }
    return rows;
}

/// The vertical load the walls carry at `time` (s): minus the sum of force_z over the rows of
/// wall_forces.csv at that output instant.
inline double walls_load_z(const std::string& out, double time) {
    double load = 0.0;
    for (const WallForceRow& row : wall_force_rows(out)) {
        if (std::abs(row.time - time) < 1e-9) {
            load -= row.force[2];
        }
    }
    return load;
}

} // namespace grainload::testing
