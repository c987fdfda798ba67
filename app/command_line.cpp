#include "app/command_line.hpp"

#include "io/case_error.hpp"

#include <string_view>

namespace grainload::app {

const char* usage() {
    return "usage:\n"
           "  grainload run CASE.toml [--out DIR] [--threads N] [--set key=value ...]\n"
           "                          [--restart DIR/checkpoint.bin]\n"
           "  grainload check CASE.toml [--set key=value ...]\n"
           "  grainload matpoint DRIVER.toml --out FILE.csv\n"
           "  grainload trade CASE.toml --vary KEY=V1,V2,... [--link KEY=W1,W2,...] --out DIR\n"
           "                  [--figures NAME,...] [--budget 2%] [--jobs N] [--threads N]\n"
           "                  [--reference KEY=V] [--set key=value ...]\n"
           "  grainload --version\n"
           "\n"
           "  --out DIR        output directory (default out/<case name>)\n"
           "  --threads N      OpenMP threads (default: all cores)\n"
           "  --set key=value  override a case key, e.g. --set sph.body[0].spacing=\"5 mm\"\n"
           "  --restart FILE   continue a run from its checkpoint\n"
           "exit codes: 0 done, 1 system error, 2 bad input, 3 run became unstable\n";
}

namespace {

CommandLine::Command command_of(std::string_view word) {
    if (word == "run") {
        return CommandLine::Command::run;
    }
    if (word == "check") {
        return CommandLine::Command::check;
    }
    if (word == "matpoint") {
        return CommandLine::Command::matpoint;
    }
    if (word == "--version" || word == "version") {
        return CommandLine::Command::version;
    }
    if (word == "--help" || word == "-h" || word == "help") {
        return CommandLine::Command::help;
    }
    throw io::CaseError("command line: unknown command '" + std::string(word) +
                        "', expected run, check, matpoint, trade or --version\n" + usage());
}

} // namespace

CommandLine parse_command_line(int argc, const char* const* argv) {
    CommandLine line;
    if (argc < 2) {
        return line;
    }
    line.command = command_of(argv[1]);
    auto value_of = [&](int& i, std::string_view option) -> std::string {
        if (i + 1 >= argc) {
            throw io::CaseError("command line: " + std::string(option) + " expects a value");
        }
        return argv[++i];
    };
    for (int i = 2; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--out") {
            line.out = value_of(i, arg);
        } else if (arg == "--threads") {
            const std::string text = value_of(i, arg);
            std::size_t used = 0;
            int threads = 0;
            try {
                threads = std::stoi(text, &used);
            } catch (const std::exception&) {
            }
            if (used != text.size() || threads < 1) {
                throw io::CaseError("command line: --threads expects a positive integer, got '" +
                                    text + "'");
            }
            line.threads = threads;
        } else if (arg == "--set") {
            line.overrides.push_back(value_of(i, arg));
        } else if (arg == "--restart") {
            line.restart = value_of(i, arg);
        } else if (!arg.starts_with("-") && line.input.empty()) {
            line.input = arg;
        } else {
            throw io::CaseError("command line: unexpected argument '" + std::string(arg) + "'\n" +
                                usage());
        }
    }
    const bool needs_input = line.command == CommandLine::Command::run ||
                             line.command == CommandLine::Command::check ||
                             line.command == CommandLine::Command::matpoint;
    if (needs_input && line.input.empty()) {
        throw io::CaseError("command line: missing the input file\n" + std::string(usage()));
    }
    return line;
}

} // namespace grainload::app
