// scripts/render_frames.py end to end: a small coupled case (sand on a 2 mm steel plate) run for
// 0.1 s, one frame rendered off screen under xvfb-run, the PNG read back. A picture for a report
// must have the size asked for, show the scene, and carry a colour bar whose range holds the
// frame's data: the bar's top at or above the largest value, and near it.
#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <regex>
#include <set>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>

namespace grainload::testing {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 400;

/// `command` through the shell, its stdout and stderr into `log`; the exit code and the output.
CliResult run_shell(const std::string& command, const std::string& log) {
    const int status = std::system((command + " > '" + log + "' 2>&1").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(log)};
}

/// Whether Debian's python3 with python3-vtk9 and xvfb-run are installed
/// (scripts/ensure_packages.sh installs them; scripts/test.sh runs it first).
bool renderer_available() {
    return std::system("command -v xvfb-run > /dev/null 2>&1 && /usr/bin/python3 -c "
                       "'import vtkmodules.vtkRenderingOpenGL2' > /dev/null 2>&1") == 0;
}

/// The range and largest value render_frames.py reports for the picture it wrote.
struct Reported {
    double low = std::nan("");
    double high = std::nan("");
    double largest = std::nan("");
};

Reported reported(const std::string& output) {
    const std::regex line(
        R"(colour range ([-+0-9.eE]+) to ([-+0-9.eE]+) \S+, largest ([-+0-9.eE]+))");
    std::smatch m;
    Reported r;
    if (std::regex_search(output, m, line)) {
        r = {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
    }
    return r;
}

/// The largest particle speed (m/s) of block `sand` and the largest von Mises stress of the
/// shell `plate`'s three surfaces (MPa) in the frame, read with VTK's own reader.
double largest_speed(const std::string& vtm) {
    const auto sand = read_named_block(vtm, "sand");
    vtkDataArray* v = sand->GetPointData()->GetArray("velocity");
    double largest = 0.0;
    for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i) {
        const double* u = v->GetTuple3(i);
        largest = std::max(largest, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
    }
    return largest;
}

double largest_von_mises_mpa(const std::string& vtm) {
    const auto plate = read_named_block(vtm, "plate");
    double largest = 0.0;
    for (const char* face : {"von_mises_top", "von_mises_middle", "von_mises_bottom"}) {
        vtkDataArray* s = plate->GetCellData()->GetArray(face);
        for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i) {
            largest = std::max(largest, s->GetTuple1(i) / 1e6);
        }
    }
    return largest;
}

/// What a picture shows: its size, and the share of the scene's part (the left 60 %, clear of
/// the colour bar's column on the right) drawn in saturated colours, i.e. by the colour map.
struct Picture {
    int width = 0;
    int height = 0;
    double coloured = 0.0;
    std::size_t colours = 0;
};

Picture look_at(const std::string& png) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    Picture p{dims[0], dims[1], 0.0, 0};
    std::set<long> distinct;
    long saturated = 0;
    const int scene_width = static_cast<int>(0.6 * dims[0]);
    for (int y = 0; y < dims[1]; ++y) {
        for (int x = 0; x < scene_width; ++x) {
            const auto* c = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            const int hi = std::max({c[0], c[1], c[2]});
            const int lo = std::min({c[0], c[1], c[2]});
            // Saturation (max - min) / max above one half: a colour of the blue-to-red map,
            // not the white ground, the black text or the grey translucent walls.
            saturated += (hi > 0 && 2 * (hi - lo) > hi) ? 1 : 0;
            distinct.insert((long(c[0]) << 16) | (long(c[1]) << 8) | long(c[2]));
        }
    }
    p.coloured = double(saturated) / (double(scene_width) * dims[1]);
    p.colours = distinct.size();
    return p;
}

class RenderFrames : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        run_ = new CaseRun(run_case_file("cases/sand_on_plate/sand_on_plate_small.toml",
                                         "render_frames", "--set 'case.end_time=0.1 s'"));
    }
    static void TearDownTestSuite() {
        delete run_;
        run_ = nullptr;
    }
    /// render_frames.py on the run's frame at 0.1 s, coloured by `colour`; its output.
    CliResult render(const std::string& colour) {
        // ctest runs the two tests side by side: each looks for a free display from its own
        // number up, so that two X servers do not race for the same one.
        const std::string display = std::to_string(100 + ::getpid() % 20000);
        const std::string command = "xvfb-run -a -n " + display + " /usr/bin/python3 '" +
                                    source_path("scripts/render_frames.py") + "' '" + run_->out +
                                    "' --times 0.1 --color " + colour + " --size " +
                                    std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                                    " --prefix " + colour;
        return run_shell(command, run_->out + "_" + colour + ".log");
    }
    static CaseRun* run_;
};
CaseRun* RenderFrames::run_ = nullptr;

// The bar's top is the next round number above the largest value: at most 25 % above it
// (frame_annotations.py: the widest step of its list of round tops, 2 to 2.5, 4 to 5, 8 to 10).
constexpr double kRoundTop = 1.25;
// The printed largest value has six significant digits.
constexpr double kPrinted = 1e-5;
// An empty scene leaves no saturated pixel in the scene's part of the picture; the sand's 2000
// particles or the coloured plate cover a tenth or more of it at this size. 1 % is about a
// hundred particles of 4 pixels: the scene is drawn, not a blank or black picture.
constexpr double kDrawn = 0.01;
// The shaded colour map gives hundreds of colours; a blank picture has one, text adds grey.
constexpr std::size_t kColours = 50;

TEST_F(RenderFrames, ParticlesBySpeedFillThePictureOfTheSizeAskedWithTheDataInTheColourRange) {
    if (!renderer_available()) {
        GTEST_SKIP() << "xvfb-run or python3-vtk9 is not installed (scripts/ensure_packages.sh)";
    }
    ASSERT_EQ(run_->cli.exit_code, 0) << run_->cli.output;
    const CliResult r = render("velocity");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Picture p = look_at(run_->out + "/pictures/velocity_t0010.png");
    EXPECT_EQ(p.width, kWidth);
    EXPECT_EQ(p.height, kHeight);
    EXPECT_GT(p.coloured, kDrawn);
    EXPECT_GT(p.colours, kColours);
    const double largest = largest_speed(frame_path(run_->out, "sand_on_plate_small", 2));
    ASSERT_GT(largest, 0.0);
    const Reported bar = reported(r.output);
    EXPECT_EQ(bar.low, 0.0) << r.output;
    EXPECT_NEAR(bar.largest, largest, kPrinted * largest) << r.output;
    EXPECT_GE(bar.high, largest) << r.output;
    EXPECT_LE(bar.high, kRoundTop * largest) << r.output;
}

TEST_F(RenderFrames, ShellByVonMisesStressShowsItsLargestValueInsideTheColourRange) {
    if (!renderer_available()) {
        GTEST_SKIP() << "xvfb-run or python3-vtk9 is not installed (scripts/ensure_packages.sh)";
    }
    ASSERT_EQ(run_->cli.exit_code, 0) << run_->cli.output;
    const CliResult r = render("von_mises");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Picture p = look_at(run_->out + "/pictures/von_mises_t0010.png");
    EXPECT_EQ(p.width, kWidth);
    EXPECT_EQ(p.height, kHeight);
    EXPECT_GT(p.coloured, kDrawn);
    EXPECT_GT(p.colours, kColours);
    const double largest = largest_von_mises_mpa(frame_path(run_->out, "sand_on_plate_small", 2));
    ASSERT_GT(largest, 0.0);
    const Reported bar = reported(r.output);
    EXPECT_EQ(bar.low, 0.0) << r.output;
    EXPECT_NEAR(bar.largest, largest, kPrinted * largest) << r.output;
    EXPECT_GE(bar.high, largest) << r.output;
    EXPECT_LE(bar.high, kRoundTop * largest) << r.output;
}

} // namespace
} // namespace grainload::testing
