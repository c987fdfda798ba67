#include "app/case_schema.hpp"
#include "app/command_line.hpp"
#include "app/notices.hpp"
#include "app/resources/heap_trim.hpp"
#include "app/resources/openmp_wait.hpp"
#include "app/run_driver.hpp"
#include "app/trade/trade_command.hpp"
#include "io/case_error.hpp"
#include "io/version.hpp"
#include "materials/material_point_reader.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

/// `grainload matpoint`: its warnings and failure printed as the driver gives them, also when
/// it refuses the driver.
int run_material_point(const grainload::app::CommandLine& line) {
    std::vector<std::string> notices;
    int code = 0;
    try {
        code = grainload::materials::run_material_point(line.input, *line.out, notices);
    } catch (...) {
        grainload::app::print_notices(notices);
        throw;
    }
    grainload::app::print_notices(notices);
    return code;
}

} // namespace

int main(int argc, char** argv) {
    using namespace grainload;
    app::default_openmp_wait(argv);
    app::keep_freed_heap();
    try {
        const app::CommandLine line = app::parse_command_line(argc, argv);
        switch (line.command) {
        case app::CommandLine::Command::run:
            return app::run_case(line);
        case app::CommandLine::Command::check:
            return app::check_case(line);
        case app::CommandLine::Command::matpoint:
            if (!line.out) {
                throw io::CaseError("command line: matpoint expects --out FILE.csv");
            }
            return run_material_point(line);
        case app::CommandLine::Command::trade:
            return app::trade_main(argc, argv);
        case app::CommandLine::Command::version:
            std::cout << "grainload " << kVersion << " (" << kGitHash << ")\n";
            return app::kExitOk;
        case app::CommandLine::Command::help:
            std::cout << (line.help_topic.empty()     ? std::string(app::usage())
                          : line.help_topic == "keys" ? app::key_help(line.help_table)
                                                      : app::usage(line.help_topic));
            return app::kExitOk;
        }
    } catch (const io::CaseError& error) {
        std::cerr << "grainload: error: " << error.what() << '\n';
        return app::kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "grainload: system error: " << error.what() << '\n';
        return app::kExitSystemError;
    }
    return app::kExitSystemError;
}
