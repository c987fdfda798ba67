// 2D granular column collapse in the configuration of the peer comparison (SPHinXsys
// `test_2d_column_collapse`, the configuration most papers share;
// cases/column_collapse_2d/column_collapse_2d.toml: a 0.2 x 0.1 m column of 5000 grains at
// 2 mm against a back wall, 0.8 s). Runs the case as `grainload run` does (frames, checkpoints
// and summary included) and prints the wall time, the steps, the particle-steps per second of
// the grains and the deposit measured as cases/column_collapse_2d/analyse.py measures it,
// beside the peer figures: SPHinXsys 258 s on two threads, grainload before the speed work
// (the build of 2026-12-01) 253 s, and the experiment. The target is 5x the peer: 51.6 s.
//
// usage: column_collapse_2d [--threads N] [--set key=value ...] [CASE.toml]
//        column_collapse_2d --analyse OUT   (the deposit of an existing run's last frame)
//   --set is passed to the run (e.g. --set 'case.end_time=0.1 s' for a short check).

#include "app/command_line.hpp"
#include "app/resources/heap_trim.hpp"
#include "app/resources/openmp_wait.hpp"
#include "app/run_driver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkDataArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

namespace {

namespace fs = std::filesystem;

/// Peer figures measured side by side on a 2-core Intel Xeon (2026-12-01, two threads).
constexpr double kPeerSeconds = 258.0;   ///< SPHinXsys, mean of 3 runs
constexpr double kBeforeSeconds = 253.0; ///< grainload of 2026-12-01, mean of 3 runs
constexpr double kTargetSpeedUp = 5.0;   ///< the speed target: 5x the peer
constexpr double kPeerEndTime = 0.8;     ///< s, the compared run
constexpr double kLink = 1.5;            ///< analyse.py LINK: bulk contact, spacings
constexpr double kThickFraction = 0.05;  ///< analyse.py THICK_FRACTION of H0 (L5%)

struct Particle {
    double x, y;   ///< final position
    double x0, y0; ///< initial position (position - displacement)
};

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

double json_number(const std::string& text, const std::string& key) {
    const std::regex pattern("\"" + key + "\": ([-+0-9.eE]+)");
    std::smatch match;
    return std::regex_search(text, match, pattern) ? std::stod(match[1]) : std::nan("");
}

/// The column's particles in the last frame of `out` (block 0 of the .vtm: the first body).
std::vector<Particle> last_frame(const std::string& out) {
    std::vector<std::string> frames;
    for (const auto& entry : fs::directory_iterator(out + "/frames")) {
        if (entry.path().extension() == ".vtm") {
            frames.push_back(entry.path().string());
        }
    }
    std::sort(frames.begin(), frames.end());
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName(frames.back().c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    auto* body = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
    vtkDataArray* displacement = body->GetPointData()->GetArray("displacement");
    std::vector<Particle> particles;
    for (vtkIdType i = 0; i < body->GetNumberOfPoints(); ++i) {
        double x[3];
        body->GetPoint(i, x);
        const double* u = displacement->GetTuple3(i);
        particles.push_back({x[0], x[1], x[0] - u[0], x[1] - u[1]});
    }
    return particles;
}

/// Largest connected set under "centres closer than link" (union-find over a cell grid).
std::vector<char> bulk_of(const std::vector<Particle>& p, double link) {
    const auto n = static_cast<int>(p.size());
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    };
    std::map<std::pair<long, long>, std::vector<int>> cells;
    for (int i = 0; i < n; ++i) {
        cells[{std::lround(std::floor(p[i].x / link)), std::lround(std::floor(p[i].y / link))}]
            .push_back(i);
    }
    for (const auto& [key, members] : cells) {
        for (long dx = -1; dx <= 1; ++dx) {
            for (long dy = -1; dy <= 1; ++dy) {
                const auto other = cells.find({key.first + dx, key.second + dy});
                if (other == cells.end()) {
                    continue;
                }
                for (const int i : members) {
                    for (const int j : other->second) {
                        const double r2 = (p[i].x - p[j].x) * (p[i].x - p[j].x) +
                                          (p[i].y - p[j].y) * (p[i].y - p[j].y);
                        if (j > i && r2 < link * link) {
                            parent[std::max(find(i), find(j))] = std::min(find(i), find(j));
                        }
                    }
                }
            }
        }
    }
    std::vector<int> size(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i) {
        ++size[find(i)];
    }
    const int root = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
    std::vector<char> bulk(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        bulk[i] = find(i) == root;
    }
    return bulk;
}

struct Deposit {
    double l0, h0;    ///< initial column, m
    double run_out;   ///< L_inf, m
    double run_out_5; ///< L_5%, m
    double height;    ///< H_inf, m
    int outside;      ///< particles not in the bulk
};

/// analyse.py's deposit(): x, y from the column's initial back face and base.
Deposit measure(const std::vector<Particle>& p) {
    std::vector<double> xs;
    for (const Particle& q : p) {
        xs.push_back(std::round(q.x0 * 1e9) / 1e9);
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::vector<double> gaps;
    for (std::size_t k = 1; k < xs.size(); ++k) {
        gaps.push_back(xs[k] - xs[k - 1]);
    }
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
    const double dp = gaps[gaps.size() / 2];
    double x_min = 1e30, y_min = 1e30, x_max = -1e30, y_max = -1e30;
    for (const Particle& q : p) {
        x_min = std::min(x_min, q.x0);
        y_min = std::min(y_min, q.y0);
        x_max = std::max(x_max, q.x0);
        y_max = std::max(y_max, q.y0);
    }
    const double x0 = x_min - 0.5 * dp;
    const double y0 = y_min - 0.5 * dp;
    Deposit d{x_max + 0.5 * dp - x0, y_max + 0.5 * dp - y0, 0.0, 0.0, 0.0, 0};
    const std::vector<char> bulk = bulk_of(p, kLink * dp);
    const double width = 2.0 * dp;
    std::vector<double> top;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!bulk[i]) {
            ++d.outside;
            continue;
        }
        d.run_out = std::max(d.run_out, p[i].x + 0.5 * dp - x0);
        d.height = std::max(d.height, p[i].y + 0.5 * dp - y0);
        const auto bin = static_cast<std::size_t>((p[i].x - x0) / width);
        top.resize(std::max(top.size(), bin + 1), 0.0);
        top[bin] = std::max(top[bin], p[i].y - y0 + 0.5 * dp);
    }
    // front_at(): the largest x where the profile reaches 5 % of H0, linear between bins.
    const double thickness = kThickFraction * d.h0;
    for (std::size_t k = top.size(); k-- > 0;) {
        if (top[k] >= thickness) {
            const double xk = (static_cast<double>(k) + 0.5) * width;
            d.run_out_5 =
                k + 1 < top.size() ? xk + (top[k] - thickness) / (top[k] - top[k + 1]) * width : xk;
            break;
        }
    }
    return d;
}

} // namespace

int main(int argc, char** argv) {
    grainload::app::default_openmp_wait(argv); // the product default, as grainload run
    grainload::app::keep_freed_heap();
    using grainload::app::CommandLine;
    CommandLine line;
    line.command = CommandLine::Command::run;
    line.input =
        std::string(GRAINLOAD_SOURCE_DIR) + "/cases/column_collapse_2d/column_collapse_2d.toml";
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--analyse" && a + 1 < argc) {
            const Deposit d = measure(last_frame(argv[++a]));
            std::printf(
                "(L_inf - L0) / L0 %.3f  (L_5%% - L0) / L0 %.3f  H_inf %.4f m  outside %d\n",
                (d.run_out - d.l0) / d.l0, (d.run_out_5 - d.l0) / d.l0, d.height, d.outside);
            return 0;
        }
        if (arg == "--threads" && a + 1 < argc) {
            line.threads = std::atoi(argv[++a]);
        } else if (arg == "--set" && a + 1 < argc) {
            line.overrides.push_back(argv[++a]);
        } else {
            line.input = arg;
        }
    }
    const std::string out =
        (fs::temp_directory_path() /
         ("grainload_bench_column_collapse_2d_" + std::to_string(static_cast<long>(getpid()))))
            .string();
    fs::remove_all(out);
    line.out = out;
    const int code = grainload::app::run_case(line);
    if (code != grainload::app::kExitOk) {
        std::fprintf(stderr, "column_collapse_2d: the run ended with exit code %d (%s)\n", code,
                     out.c_str());
        return code;
    }
    const std::string summary = read_text(out + "/summary.json");
    const double seconds = json_number(summary, "wall_time_s");
    const double steps = json_number(summary, "steps");
    const double grains = json_number(summary, "material_points");
    const Deposit d = measure(last_frame(out));
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    const char* spins = std::getenv("GOMP_SPINCOUNT");
    std::printf("# 2D column collapse (%s), %d thread(s), OMP_WAIT_POLICY=%s GOMP_SPINCOUNT=%s\n",
                line.input.c_str(), static_cast<int>(json_number(summary, "threads")),
                policy != nullptr ? policy : "(unset)", spins != nullptr ? spins : "(unset)");
    std::printf("%-34s %12s %12s %12s\n", "", "this run", "grainload", "SPHinXsys");
    std::printf("%-34s %12s %12s %12s\n", "", "", "before", "peer");
    std::printf("%-34s %12.1f %12.1f %12.1f\n", "wall time, s (2 threads for peers)", seconds,
                kBeforeSeconds, kPeerSeconds);
    std::printf("%-34s %12.0f %12d %12d\n", "steps", steps, 64027, 38083);
    std::printf("%-34s %12.3f %12.2f %12.2f\n", "us per grain-step (wall)",
                1e6 * seconds / (steps * grains), 0.79, 1.36);
    std::printf("%-34s %12.3e\n", "grain-steps per second", grains * steps / seconds);
    std::printf("%-34s %12.3f %12.3f %12.2f\n", "(L_inf - L0) / L0", (d.run_out - d.l0) / d.l0,
                0.995, 1.21);
    std::printf("%-34s %12.3f %12.3f %12.2f\n", "(L_5% - L0) / L0", (d.run_out_5 - d.l0) / d.l0,
                0.963, 1.08);
    std::printf("%-34s %12.4f %12.4f %12.4f\n", "H_inf, m", d.height, 0.0995, 0.100);
    std::printf("%-34s %12d\n", "grains outside the bulk", d.outside);
    std::printf("grainload before the speed work and SPHinXsys: measured side by side on a 2-core "
                "Intel Xeon, 2026-12-01, two threads, wall time the mean of 3 runs\n");
    std::printf("experiment (Bui et al. 2008 as quoted, docs/validation/column_collapse_2d.md): "
                "(L_inf - L0)/L0 ~ 0.9-1.0, H_inf = H0 = %.3f m\n",
                d.h0);
    const double target = kPeerSeconds / kTargetSpeedUp;
    if (std::abs(json_number(summary, "simulated_time_s") - kPeerEndTime) > 1e-9) {
        std::printf("target (5x the peer): %.1f s for the full %.1f s; this run is shorter, not "
                    "compared\n",
                    target, kPeerEndTime);
    } else {
        std::printf(
            "target (5x the peer): %.1f s = SPHinXsys / %.0f; this run %.2fx the peer: %s\n",
            target, kTargetSpeedUp, kPeerSeconds / seconds, seconds <= target ? "met" : "NOT met");
    }
    fs::remove_all(out);
    return 0;
}
