#include "app/trade/trade_command.hpp"

#include "app/resources/memory_guard.hpp"
#include "app/resources/process_pool.hpp"
#include "app/scene.hpp"
#include "app/trade/trade_report.hpp"
#include "app/trade/trade_table.hpp"
#include "io/atomic_file.hpp"
#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/json_value.hpp"
#include "io/scene_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace grainload::app {

namespace {

namespace fs = std::filesystem;

const char* const kUsage =
    "  grainload trade CASE.toml --vary KEY=V1,V2,... [--link KEY=W1,W2,...] [--vary ...]\n"
    "                  --out DIR [--figures NAME,...] [--budget 2%] [--jobs N] [--threads N]\n"
    "                  [--reference KEY=V] [--noise N] [--set key=value ...]\n";

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        if (!part.empty()) {
            parts.push_back(part);
        }
    }
    return parts;
}

int positive_integer(const std::string& text, const std::string& option) {
    std::size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(text, &used);
    } catch (const std::exception&) {
    }
    if (used != text.size() || value < 1) {
        throw io::CaseError("command line: " + option + " expects a positive integer, got '" +
                            text + "'");
    }
    return value;
}

/// FNV-1a of the case file's text: a resumed sweep must run the same case.
std::string text_hash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::uint64_t hash = 1469598103934665603ULL;
    for (const char c : text.str()) {
        hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    }
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(hash));
    return out;
}

std::string json_strings(const std::vector<std::string>& items) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
        out += (i == 0 ? "" : ", ") + io::json_quoted(items[i]);
    }
    return out + "]";
}

std::vector<std::string> strings_of(const io::JsonValue* array) {
    std::vector<std::string> out;
    if (array != nullptr) {
        for (const io::JsonValue& item : array->array) {
            out.push_back(item.string);
        }
    }
    return out;
}

/// DIR/trade.json names the case and the overrides common to all runs; a later invocation on
/// the same DIR must give the same ones (the grid itself may grow or shrink).
void check_manifest(const TradeOptions& o, const std::string& case_path) {
    const std::string path = o.out + "/trade.json";
    const std::string hash = text_hash(case_path);
    if (fs::exists(path)) {
        const io::JsonValue manifest = io::read_json_file(path);
        const bool same_case = manifest.string_at("case_hash") == hash;
        const bool same_overrides = strings_of(manifest.find("overrides")) == o.overrides;
        if (!same_case || !same_overrides) {
            throw io::CaseError(
                "command line: --out " + o.out + " holds a sweep of " +
                manifest.string_at("case_file").value_or("another case") +
                (same_case ? " with other --set overrides" : " as the case file was then") +
                "; its runs cannot be reused: give another --out");
        }
        return;
    }
    io::write_file_atomically(path, [&](std::ostream& out) {
        out << "{\n  \"case_file\": " << io::json_quoted(case_path)
            << ",\n  \"case_hash\": " << io::json_quoted(hash)
            << ",\n  \"overrides\": " << json_strings(o.overrides) << "\n}\n";
    });
}

/// Runs end in a record DIR/<id>/trade_run.json. Finished: recorded with these overrides and an
/// exit code that a rerun would repeat (0 done, 2 bad input, 3 unstable).
struct RunRecord {
    int exit_code = -1;
    double elapsed_s = 0.0;
};

std::optional<RunRecord> finished_record(const std::string& directory, const TradeRun& run) {
    const std::string path = directory + "/trade_run.json";
    if (!fs::exists(path)) {
        return std::nullopt;
    }
    const io::JsonValue record = io::read_json_file(path);
    if (strings_of(record.find("overrides")) != run.overrides) {
        throw io::CaseError(path + ": this run was made with other overrides (" +
                            json_strings(strings_of(record.find("overrides"))) +
                            "); give another --out");
    }
    const int code = static_cast<int>(record.number_at("exit_code").value_or(-1));
    if (code != 0 && code != 2 && code != 3) {
        return std::nullopt;
    }
    return RunRecord{code, record.number_at("elapsed_s").value_or(0.0)};
}

void write_record(const std::string& directory, const TradeRun& run, const ProcessResult& r) {
    io::write_file_atomically(directory + "/trade_run.json", [&](std::ostream& out) {
        out << "{\n  \"overrides\": " << json_strings(run.overrides)
            << ",\n  \"exit_code\": " << r.exit_code << ",\n  \"signal\": " << r.signal
            << ",\n  \"elapsed_s\": " << io::json_number(r.elapsed_s) << "\n}\n";
    });
}

ProcessSpec run_command(const TradeOptions& o, const std::string& case_path, const TradeRun& run,
                        int threads) {
    const std::string directory = o.out + "/" + run.id;
    ProcessSpec spec;
    spec.argv = {fs::read_symlink("/proc/self/exe").string(),
                 "run",
                 case_path,
                 "--out",
                 directory,
                 "--threads",
                 std::to_string(threads)};
    for (const auto* list : {&o.overrides, &run.overrides}) {
        for (const std::string& assignment : *list) {
            spec.argv.push_back("--set");
            spec.argv.push_back(assignment);
        }
    }
    spec.log_file = directory + "/console.txt";
    return spec;
}

/// scripts/plot_trade.py DIR/trade.csv DIR/trade.svg; says why when it cannot draw.
void plot(const TradeOptions& o) {
    const std::string script = std::string(GRAINLOAD_SCRIPTS_DIR) + "/plot_trade.py";
    ProcessSpec spec;
    // Debian's interpreter, which python3-matplotlib serves (scripts/ensure_packages.sh).
    spec.argv = {"/usr/bin/python3",   script,     o.out + "/trade.csv",
                 o.out + "/trade.svg", "--budget", std::to_string(o.budget)};
    spec.log_file = o.out + "/plot_log.txt";
    const ProcessResult r = run_process(spec);
    if (r.exit_code == 0) {
        std::printf("plot: %s/trade.svg\n", o.out.c_str());
        return;
    }
    std::ifstream log(spec.log_file);
    std::string line;
    std::string last;
    while (std::getline(log, line)) {
        last = line.empty() ? last : line;
    }
    std::printf("plot skipped (%s); trade.csv is complete\n",
                last.empty() ? "python3 could not be started" : last.c_str());
}

/// The commands of the runs still to do, their directories made and emptied of a summary an
/// interrupted attempt may have left.
std::vector<ProcessSpec> prepare_runs(const TradeOptions& o, const std::string& case_path,
                                      const std::vector<TradeRun>& grid,
                                      const std::vector<std::size_t>& pending, int threads) {
    std::vector<ProcessSpec> commands;
    for (const std::size_t r : pending) {
        const std::string directory = o.out + "/" + grid[r].id;
        fs::create_directories(directory);
        fs::remove(directory + "/summary.json");
        commands.push_back(run_command(o, case_path, grid[r], threads));
    }
    return commands;
}

/// The most accurate run's round-off members (--noise), built from the case's gravity under
/// that run's overrides (set on `document`, which holds the case and the common overrides);
/// refused for a case without gravity.
std::vector<TradeRun> ensemble_runs(const TradeOptions& o, io::CaseDocument& document,
                                    const std::string& case_path, const TradeRun& best) {
    for (const std::string& assignment : best.overrides) {
        document.set(assignment);
    }
    const io::SceneSettings scene =
        io::read_scene_settings(document, fs::path(case_path).stem().string());
    if (scene.gravity.norm() == 0.0) {
        throw io::CaseError("command line: --noise perturbs gravity by parts in 1e8 to measure "
                            "each figure's round-off scatter, and this case has no gravity");
    }
    return noise_runs(best, {scene.gravity[0], scene.gravity[1], scene.gravity[2]}, scene.dimension,
                      o.noise);
}

/// An axis without an accuracy rule needs --reference, unless its key is misspelt: then no
/// value is more accurate than another, and asking for --reference would send the user the wrong
/// way. The case is loaded as `grainload check` loads it, with the common overrides and the
/// grid's first run's values (each named by its flag), so that a key no reader knows is refused
/// as `grainload run --set` refuses it (exit 2, naming the key). Only a sweep with such an axis
/// pays for the load.
void check_unruled_keys(const TradeOptions& o, const std::string& case_path,
                        const TradeRun& first) {
    const bool unruled = std::any_of(o.axes.begin(), o.axes.end(), [](const TradeAxis& axis) {
        return !axis.reference && accuracy_rule(axis.key) == AccuracyRule::none;
    });
    if (!unruled) {
        return;
    }
    auto document = io::CaseDocument::from_file(case_path);
    for (const std::string& assignment : o.overrides) {
        document->set(assignment);
    }
    // first.overrides: each axis' value, then its linked keys' (trade_grid).
    std::size_t k = 0;
    for (const TradeAxis& axis : o.axes) {
        document->set(first.overrides[k++], "--vary");
        for (std::size_t l = 0; l < axis.linked.size(); ++l) {
            document->set(first.overrides[k++], "--link");
        }
    }
    Scene::from_document(std::move(document), fs::path(case_path).stem().string(),
                         available_memory());
}

/// A sweep whose runs all failed is no trade (every run refusing a misspelt key, say): the
/// first run's diagnosis from its console.txt, and its exit code (2 bad input, 3 unstable; 1
/// for anything else) as the sweep's.
int report_failure(const TradeOptions& o, const std::vector<TradeRun>& grid,
                   const std::vector<TradeResult>& results) {
    const std::string console = o.out + "/" + grid.front().id + "/console.txt";
    std::ifstream in(console);
    std::string line;
    std::string said;
    std::string last;
    while (std::getline(in, line)) {
        if (line.starts_with("grainload: error") || line.find("became unstable") != line.npos) {
            said += "  " + line + "\n";
        }
        last = line.empty() ? last : line;
    }
    said = said.empty() && !last.empty() ? "  " + last + "\n" : said;
    const int code = results.front().exit_code;
    std::fprintf(stderr,
                 "grainload: error: trade: every run failed; the first, %s (exit %d, %s), "
                 "said:\n%s",
                 grid.front().id.c_str(), code, console.c_str(),
                 said.empty() ? "  nothing\n" : said.c_str());
    return code == 2 || code == 3 ? code : 1;
}

/// The plot of a sweep that has a run to show, 0; else report_failure's code.
int finish(const TradeOptions& o, const std::vector<TradeRun>& grid,
           const std::vector<TradeResult>& results) {
    if (std::none_of(results.begin(), results.end(),
                     [](const TradeResult& r) { return r.exit_code == 0; })) {
        return report_failure(o, grid, results);
    }
    plot(o);
    return 0;
}

} // namespace

const char* trade_usage() {
    return kUsage;
}

TradeOptions parse_trade_options(int argc, const char* const* argv) {
    TradeOptions o;
    std::vector<std::string> references;
    auto value_of = [&](int& i, const std::string& option) -> std::string {
        if (i + 1 >= argc) {
            throw io::CaseError("command line: " + option + " expects a value");
        }
        return argv[++i];
    };
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--vary") {
            o.axes.push_back(parse_trade_axis(value_of(i, arg), arg));
        } else if (arg == "--link") {
            link_trade_axis(o.axes, parse_trade_axis(value_of(i, arg), arg));
        } else if (arg == "--reference") {
            references.push_back(value_of(i, arg));
        } else if (arg == "--figures") {
            o.figures = split_commas(value_of(i, arg));
        } else if (arg == "--budget") {
            o.budget = parse_budget(value_of(i, arg));
        } else if (arg == "--noise") {
            o.noise = positive_integer(value_of(i, arg), arg);
            if (o.noise < 2) {
                throw io::CaseError("command line: --noise expects the ensemble's size, at least "
                                    "2 (the most accurate run and one member), got " +
                                    std::to_string(o.noise));
            }
        } else if (arg == "--jobs") {
            o.jobs = positive_integer(value_of(i, arg), arg);
        } else if (arg == "--threads") {
            o.threads = positive_integer(value_of(i, arg), arg);
        } else if (arg == "--out") {
            o.out = value_of(i, arg);
        } else if (arg == "--set") {
            o.overrides.push_back(value_of(i, arg));
        } else if (!arg.starts_with("-") && o.case_file.empty()) {
            o.case_file = arg;
        } else {
            throw io::CaseError("command line: unexpected argument '" + arg + "'\nusage:\n" +
                                kUsage);
        }
    }
    for (const std::string& reference : references) {
        set_trade_reference(o.axes, reference);
    }
    if (o.case_file.empty() || o.axes.empty() || o.out.empty()) {
        throw io::CaseError(std::string("command line: trade needs CASE.toml, at least one "
                                        "--vary and --out DIR\nusage:\n") +
                            kUsage);
    }
    return o;
}

namespace {

/// The grid of runs, the noise ensemble's members appended (their indices in `members`),
/// checked against the case: the overrides' syntax once (what they mean, by each run), the keys
/// without a rule. `best`: the most accurate run.
std::vector<TradeRun> checked_grid(const TradeOptions& o, const std::string& case_path,
                                   std::size_t& best, std::vector<std::size_t>& members) {
    auto document = io::CaseDocument::from_file(case_path);
    for (const std::string& assignment : o.overrides) {
        document->set(assignment);
    }
    std::vector<TradeRun> grid = trade_grid(o.axes);
    for (const std::string& assignment : grid.front().overrides) {
        document->set(assignment);
    }
    check_unruled_keys(o, case_path, grid.front());
    best = find_run(grid, most_accurate(o.axes));
    if (o.noise > 1) {
        for (TradeRun& member : ensemble_runs(o, *document, case_path, grid[best])) {
            members.push_back(grid.size());
            grid.push_back(std::move(member));
        }
    }
    return grid;
}

/// Runs what the grid has not finished in an earlier call, `o.jobs` at a time, each line
/// printed as it ends; every run's record.
std::vector<std::optional<RunRecord>> run_grid(const TradeOptions& o, const std::string& case_path,
                                               const std::vector<TradeRun>& grid,
                                               std::size_t best) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int threads = o.threads.value_or(std::max(1, cores / o.jobs));
    std::vector<std::optional<RunRecord>> records(grid.size());
    std::vector<std::size_t> pending;
    for (std::size_t r = 0; r < grid.size(); ++r) {
        records[r] = finished_record(o.out + "/" + grid[r].id, grid[r]);
        if (!records[r]) {
            pending.push_back(r);
        }
    }
    const std::vector<ProcessSpec> commands = prepare_runs(o, case_path, grid, pending, threads);
    std::printf("trade: %zu runs, %zu finished earlier, %zu to run (%d at a time, %d thread%s "
                "each); most accurate: %s\n",
                grid.size(), grid.size() - pending.size(), pending.size(), o.jobs, threads,
                threads == 1 ? "" : "s", grid[best].id.c_str());
    std::fflush(stdout);
    std::size_t done = 0;
    run_processes(commands, o.jobs, [&](std::size_t c, const ProcessResult& result) {
        const std::size_t r = pending[c];
        write_record(o.out + "/" + grid[r].id, grid[r], result);
        records[r] = RunRecord{result.exit_code, result.elapsed_s};
        std::printf("[%zu/%zu] %s: exit %d%s, %s\n", ++done, pending.size(), grid[r].id.c_str(),
                    result.exit_code,
                    result.signal != 0 ? (" (signal " + std::to_string(result.signal) + ")").c_str()
                                       : "",
                    seconds(result.elapsed_s).c_str());
        std::fflush(stdout);
    });
    return records;
}

} // namespace

int run_trade(const TradeOptions& o) {
    if (!fs::is_regular_file(o.case_file)) {
        throw io::CaseError("command line: " + o.case_file + " is not a readable case file");
    }
    const std::string case_path = fs::absolute(o.case_file).lexically_normal().string();
    std::size_t best = 0;
    std::vector<std::size_t> members;
    const std::vector<TradeRun> grid = checked_grid(o, case_path, best, members);
    fs::create_directories(o.out);
    check_manifest(o, case_path);
    const std::vector<std::optional<RunRecord>> records = run_grid(o, case_path, grid, best);
    std::vector<TradeResult> results;
    for (std::size_t r = 0; r < grid.size(); ++r) {
        results.push_back(read_trade_result(o.out + "/" + grid[r].id, records[r]->exit_code,
                                            records[r]->elapsed_s));
    }
    const TradeAnalysis analysis = analyse_trade(results, best, o.figures, o.budget, members);
    write_trade_csv(o.out + "/trade.csv", o.axes, grid, results, analysis);
    print_table(grid, results, analysis, o.budget);
    print_noise(analysis, o.budget);
    std::printf("table: %s/trade.csv\n", o.out.c_str());
    return finish(o, grid, results);
}

int trade_main(int argc, const char* const* argv) {
    return run_trade(parse_trade_options(argc, argv));
}

} // namespace grainload::app
