#include "io/binary_stream.hpp"
#include "particles/scene_part_list.hpp"

#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace grainload::particles {
namespace {

/// A part that writes every call it receives into a shared log and keeps one number as state.
class LoggingPart final : public ScenePart {
  public:
    LoggingPart(std::string name, std::vector<std::string>& log, double state = 0.0)
        : name_(std::move(name)), log_(&log), state_(state) {}
    std::string_view name() const override { return name_; }
    void after_step(double t, double dt) override { note("after_step", t + dt); }
    void end_step(double time) override { note("end_step", time); }
    void after_removal(std::span<const Index> new_index) override {
        note("after_removal", static_cast<double>(new_index.size()));
    }
    void append_results(std::vector<io::ResultFigure>& results) const override {
        results.push_back({name_, state_, "", std::nullopt, ""});
    }
    std::optional<std::string> diagnose() const override {
        return state_ < 0.0 ? std::optional<std::string>(name_ + " failed") : std::nullopt;
    }
    void write_checkpoint(std::ostream& out) const override { io::write_value(out, state_); }
    void read_checkpoint(std::istream& in) override { state_ = io::read_value<double>(in); }
    double state() const { return state_; }

  private:
    void note(const char* point, double value) {
        log_->push_back(name_ + ' ' + point + ' ' + std::to_string(value));
    }
    std::string name_;
    std::vector<std::string>* log_;
    double state_;
};

ScenePartList two_parts(std::vector<std::string>& log, double first, double second) {
    ScenePartList list;
    list.add(std::make_unique<LoggingPart>("sph.probe", log, first));
    list.add(std::make_unique<LoggingPart>("sph.wall_map", log, second));
    return list;
}

TEST(ScenePartList, EachPointCallsThePartsInTheOrderTheyWereAdded) {
    std::vector<std::string> log;
    ScenePartList list = two_parts(log, 1.0, 2.0);
    list.after_step(0.5, 0.25);
    const std::vector<Index> map{0, -1, 1};
    list.after_removal(map);
    list.end_step(0.75);
    EXPECT_EQ(log, (std::vector<std::string>{
                       "sph.probe after_step 0.750000", "sph.wall_map after_step 0.750000",
                       "sph.probe after_removal 3.000000", "sph.wall_map after_removal 3.000000",
                       "sph.probe end_step 0.750000", "sph.wall_map end_step 0.750000"}));
    std::vector<io::ResultFigure> results;
    list.append_results(results);
    ASSERT_EQ(results.size(), 2u);
    EXPECT_EQ(results[0].name, "sph.probe");
    EXPECT_EQ(results[1].value, 2.0);
}

TEST(ScenePartList, TheFirstPartsDiagnosisIsTheListsOne) {
    std::vector<std::string> log;
    EXPECT_FALSE(two_parts(log, 1.0, 2.0).diagnose());
    EXPECT_EQ(two_parts(log, 1.0, -1.0).diagnose(), "sph.wall_map failed");
    EXPECT_EQ(two_parts(log, -1.0, -1.0).diagnose(), "sph.probe failed");
}

TEST(ScenePartList, ACheckpointRestoresEveryPartsStateExactly) {
    std::vector<std::string> log;
    std::stringstream bytes;
    two_parts(log, 0.1, 1.0 / 3.0).write_checkpoint(bytes);
    ScenePartList restored;
    auto* first = new LoggingPart("sph.probe", log);
    auto* second = new LoggingPart("sph.wall_map", log);
    restored.add(std::unique_ptr<ScenePart>(first));
    restored.add(std::unique_ptr<ScenePart>(second));
    restored.read_checkpoint(bytes);
    EXPECT_EQ(first->state(), 0.1);
    EXPECT_EQ(second->state(), 1.0 / 3.0);
    EXPECT_EQ(bytes.peek(), std::char_traits<char>::eof());
}

TEST(ScenePartList, ARestoreIntoOtherPartsIsRefusedNamingThem) {
    std::vector<std::string> log;
    std::stringstream bytes;
    two_parts(log, 0.1, 0.2).write_checkpoint(bytes);
    const std::string written = bytes.str();

    ScenePartList swapped;
    swapped.add(std::make_unique<LoggingPart>("sph.wall_map", log));
    swapped.add(std::make_unique<LoggingPart>("sph.probe", log));
    std::stringstream in(written);
    try {
        swapped.read_checkpoint(in);
        ADD_FAILURE() << "parts in another order were restored";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "checkpoint: expected the state of the scene part sph.wall_map, "
                               "found sph.probe");
    }

    ScenePartList fewer;
    fewer.add(std::make_unique<LoggingPart>("sph.probe", log));
    std::stringstream again(written);
    try {
        fewer.read_checkpoint(again);
        ADD_FAILURE() << "a checkpoint of two parts was restored into one";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "checkpoint: it holds the state of 2 scene parts, the case "
                               "builds 1");
    }
}

} // namespace
} // namespace grainload::particles
