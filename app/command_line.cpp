#include "app/command_line.hpp"

#include "app/trade/trade_command.hpp"
#include "io/case_error.hpp"

#include <algorithm>
#include <string_view>

namespace grainload::app {

namespace {

constexpr const char* kExitCodes =
    "exit codes: 0 done, 1 system error, 2 bad input, 3 run became unstable (see summary.json)\n";

constexpr const char* kRunUsage =
    "usage: grainload run CASE.toml [--out DIR] [--threads N] [--set key=value ...]\n"
    "                               [--restart DIR/checkpoint.bin]\n"
    "  Runs the case: frames, checkpoints and summary.json in DIR.\n"
    "  --out DIR        output directory (default out/<case name>)\n"
    "  --threads N      OpenMP threads (default: all cores); 'auto': the cores other work\n"
    "                   leaves free at start (for a shared machine)\n"
    "  --set key=value  override a case key, e.g. --set sph.body[0].spacing=\"5 mm\"\n"
    "  --restart FILE   continue a run from its checkpoint\n";

constexpr const char* kCheckUsage =
    "usage: grainload check CASE.toml [--set key=value ...]\n"
    "  Reads and validates the whole case (particles and meshes included); writes nothing.\n"
    "  --set key=value  override a case key, e.g. --set case.end_time=\"1 s\"\n";

constexpr const char* kMatpointUsage =
    "usage: grainload matpoint DRIVER.toml --out FILE.csv\n"
    "  Drives one material point along a strain or stress path (docs/user-guide/matpoint.md).\n";

constexpr const char* kVersionUsage =
    "usage: grainload --version\n"
    "  Prints the release and the git commit it was built from.\n";

constexpr const char* kHelpUsage =
    "usage: grainload help [COMMAND]   (or --help, -h)\n"
    "       grainload help keys [TABLE]\n"
    "  Prints the usage overview, or that of one command; `keys`: the tables of a case file,\n"
    "  or one table's keys with their types, defaults and meanings (e.g. help keys sph.body).\n";

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
    if (word == "trade") {
        return CommandLine::Command::trade;
    }
    if (word == "--version" || word == "version") {
        return CommandLine::Command::version;
    }
    if (word == "--help" || word == "-h" || word == "help") {
        return CommandLine::Command::help;
    }
    throw io::CaseError("command line: unknown command '" + std::string(word) +
                        "', expected run, check, matpoint, trade, help or --version\n" + usage());
}

std::string command_name(CommandLine::Command command) {
    switch (command) {
    case CommandLine::Command::run:
        return "run";
    case CommandLine::Command::check:
        return "check";
    case CommandLine::Command::matpoint:
        return "matpoint";
    case CommandLine::Command::trade:
        return "trade";
    case CommandLine::Command::version:
        return "version";
    case CommandLine::Command::help:
        break;
    }
    return "";
}

bool asks_for_help(std::string_view arg) {
    return arg == "--help" || arg == "-h";
}

/// `grainload help [COMMAND]` and `grainload COMMAND ... --help`.
CommandLine help_line(int argc, const char* const* argv, CommandLine::Command command) {
    CommandLine line;
    line.command = CommandLine::Command::help;
    if (command != CommandLine::Command::help) {
        line.help_topic = command_name(command);
    } else if (argc > 2 && std::string_view(argv[2]) == "keys") {
        line.help_topic = "keys";
        if (argc > 4) {
            throw io::CaseError(std::string("command line: help keys takes at most one table\n") +
                                usage());
        }
        line.help_table = argc > 3 ? argv[3] : "";
    } else if (argc > 2) {
        line.help_topic = asks_for_help(argv[2]) ? "help" : argv[2];
        usage(line.help_topic); // an unknown topic is a bad command line
    }
    return line;
}

/// `--threads N` (a positive integer) or `--threads auto` into `line`.
void set_threads(const std::string& text, CommandLine& line) {
    if (text == "auto") {
        line.auto_threads = true;
        line.threads.reset();
        return;
    }
    line.auto_threads = false;
    std::size_t used = 0;
    int threads = 0;
    try {
        threads = std::stoi(text, &used);
    } catch (const std::exception&) {
    }
    if (used != text.size() || threads < 1) {
        throw io::CaseError("command line: --threads expects a positive integer or 'auto', got '" +
                            text + "'");
    }
    line.threads = threads;
}

} // namespace

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
           "  grainload help [COMMAND]   (or --help, -h)\n"
           "  grainload help keys [TABLE]\n"
           "\n"
           "  --out DIR        output directory (default out/<case name>)\n"
           "  --threads N      OpenMP threads (default: all cores); 'auto': the cores other work\n"
           "                   leaves free at start (for a shared machine)\n"
           "  --set key=value  override a case key, e.g. --set sph.body[0].spacing=\"5 mm\"\n"
           "  --restart FILE   continue a run from its checkpoint\n"
           "exit codes: 0 done, 1 system error, 2 bad input, 3 run became unstable "
           "(see summary.json)\n";
}

std::string usage(const std::string& command) {
    const char* text = command == "run"                                 ? kRunUsage
                       : command == "check"                             ? kCheckUsage
                       : command == "matpoint"                          ? kMatpointUsage
                       : command == "version" || command == "--version" ? kVersionUsage
                       : command == "trade"                             ? trade_usage()
                       : command == "help"                              ? kHelpUsage
                                                                        : nullptr;
    if (text == nullptr) {
        throw io::CaseError("command line: no help on '" + command +
                            "': expected run, check, matpoint, trade, version or help\n" + usage());
    }
    return std::string(text) + kExitCodes;
}

CommandLine parse_command_line(int argc, const char* const* argv) {
    CommandLine line;
    if (argc < 2) {
        return line;
    }
    line.command = command_of(argv[1]);
    // Help wins over everything else on the line, so that `grainload run --help` (perhaps after
    // a half-typed command) prints the usage instead of complaining about what is missing.
    if (line.command == CommandLine::Command::help ||
        std::any_of(argv + 2, argv + argc, [](const char* arg) { return asks_for_help(arg); })) {
        return help_line(argc, argv, line.command);
    }
    if (line.command == CommandLine::Command::trade) {
        return line; // `trade` has options of its own (app/trade/trade_command.hpp)
    }
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
            set_threads(value_of(i, arg), line);
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
