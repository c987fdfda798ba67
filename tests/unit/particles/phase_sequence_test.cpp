// The run's phases: the sequence's ends and state, and the scene part a particle method holds.

#include "io/case_table.hpp"
#include "particles/particles_case_reader.hpp"
#include "particles/phase_part.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

namespace grainload::particles {
namespace {

PhaseSequence read(const std::string& phases) {
    auto document = io::CaseDocument::from_string("[case]\ndimension = 3\n" + phases, "p.toml");
    return read_phases(document->root());
}

const char* const kFourPhases = R"(
[[phase]]
name = "fill"
end = "1.5 s"
[[phase]]
name = "settle"
end = "settled"
kinetic_energy_fraction = 0.1
[[phase]]
name = "discharge"
end = "discharged"
discharged_mass = "2 kg"
[[phase]]
name = "closed"
)";

// The starts a stated end fixes are known before the run (fill 0, settle 1.5 s), the one after
// a condition is not; the steps then end fill at the stated 1.5 s (a step end an ulp short of
// it counts), settle at the first step from 1.5 s below a tenth of the peak since t = 0 (10 J
// at 1 s: 0.5 J at 1.2 s is before the phase and does not count), discharge once the sinks
// took 2 kg more than when it began (1 kg then: at 3 kg, not at 2.5 kg).
TEST(PhaseSequence, EndsOnTimeSettleAndDischargeInOrder) {
    PhaseSequence phases = read(kFourPhases);
    EXPECT_EQ(phases.start(0), 0.0);
    EXPECT_EQ(phases.start(1), 1.5);
    EXPECT_TRUE(std::isinf(phases.start(2)));
    phases.record_kinetic(1.0, 10.0);
    phases.record_kinetic(1.2, 0.5);
    EXPECT_TRUE(phases.update(1.2, 0.0).empty());
    const double short_of = std::nextafter(1.5, 0.0);
    phases.record_kinetic(short_of, 2.0);
    const auto fill = phases.update(short_of, 0.0);
    ASSERT_EQ(fill.size(), 1u);
    EXPECT_NE(fill[0].find("phase \"fill\" ended at t = 1.5 s"), std::string::npos) << fill[0];
    phases.record_kinetic(1.75, 0.9);
    const auto settle = phases.update(1.75, 1.0);
    ASSERT_EQ(settle.size(), 1u);
    EXPECT_EQ(phases.start(2), 1.75);
    EXPECT_TRUE(phases.update(2.0, 2.5).empty());
    EXPECT_EQ(phases.update(2.25, 3.0).size(), 1u);
    EXPECT_EQ(phases.start(3), 2.25);
    std::vector<io::PhaseRecord> records;
    phases.append_records(records);
    ASSERT_EQ(records.size(), 4u);
    EXPECT_EQ(records[0].end, 1.5);
    EXPECT_EQ(records[0].ended_by, "time");
    EXPECT_EQ(records[1].ended_by, "settled");
    EXPECT_EQ(records[2].ended_by, "discharged");
    EXPECT_EQ(records[3].start, 2.25);
    EXPECT_TRUE(std::isnan(records[3].end));
    EXPECT_EQ(records[3].ended_by, "");
}

/// Settle on a condition, then a stated end the condition may pass, then an open end.
constexpr const char* kSettleOpenDischarge = R"(
[[phase]]
name = "settle"
end = "settled"
kinetic_energy_fraction = 0.1
[[phase]]
name = "open"
end = "1 s"
[[phase]]
name = "discharge"
)";

// A stated end that a condition before it outran ends its phase as it begins (both logged),
// and the state restores every start, end and watch exactly.
TEST(PhaseSequence, StatedEndPassedByAConditionEndsAtOnceAndStateRestores) {
    PhaseSequence phases = read(kSettleOpenDischarge);
    phases.record_kinetic(0.5, 10.0);
    phases.record_kinetic(2.0, 0.5);
    EXPECT_EQ(phases.update(2.0, 0.0).size(), 2u);
    EXPECT_EQ(phases.start(1), 2.0);
    EXPECT_EQ(phases.start(2), 2.0);
    PhaseSequence copy = read(kSettleOpenDischarge);
    copy.set_state(phases.state());
    EXPECT_EQ(copy.state(), phases.state());
    EXPECT_EQ(copy.start(2), 2.0);
    EXPECT_THROW(copy.set_state({0.0}), std::runtime_error);
}

/// What a method gives the part and what the part hands back: a scene whose kinetic energy and
/// discharged mass the test sets, and the starts the part handed over last.
struct Scene {
    double kinetic = 0.0;
    double discharged = 0.0;
    std::vector<double> starts;
    int handed = 0;

    PhasePart::Hooks hooks() {
        return {[this] { return kinetic; }, [this] { return discharged; },
                [this](const PhaseSequence& phases) {
                    starts = {phases.start(1), phases.start(2), phases.start(3)};
                    ++handed;
                }};
    }
};

// The part records the kinetic energy after each step (a tenth of the 10 J peak: 0.5 J at
// 1.75 s settles), ends the phases only when the method advances it, hands the starts over at
// each end, logs each end once, and reports the settle figures; a second part restored from its
// checkpoint holds the same state, hands the starts over at once, and has no events to log.
TEST(PhasePart, ReadsTheMethodThroughItsHooksAndRestoresItsState) {
    Scene scene;
    PhasePart part(read(kFourPhases), scene.hooks(), true);
    part.apply_starts();
    EXPECT_EQ(scene.starts[0], 1.5);
    EXPECT_TRUE(std::isinf(scene.starts[1]));
    scene.kinetic = 10.0;
    part.after_step(0.75, 0.25);
    EXPECT_TRUE(part.advance(1.5));
    scene.kinetic = 0.5;
    part.after_step(1.5, 0.25);
    EXPECT_TRUE(std::isinf(scene.starts[1])) << "ended before advance";
    EXPECT_TRUE(part.advance(1.75));
    EXPECT_EQ(scene.starts[1], 1.75);
    scene.discharged = 1.0;
    EXPECT_FALSE(part.advance(2.0));
    std::ostringstream saved;
    part.write_checkpoint(saved);
    scene.discharged = 3.0;
    EXPECT_TRUE(part.advance(2.25));
    EXPECT_EQ(scene.starts[2], 2.25);
    std::vector<std::string> events;
    part.take_events(events);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_NE(events[1].find("phase \"settle\" ended at t = 1.75 s"), std::string::npos)
        << events[1];
    part.take_events(events);
    EXPECT_EQ(events.size(), 3u);
    std::vector<io::ResultFigure> results;
    part.append_results(results);
    ASSERT_FALSE(results.empty());
    EXPECT_EQ(results[0].name, "settle_time");
    EXPECT_EQ(results[0].value, 1.75);

    Scene restored_scene;
    PhasePart restored(read(kFourPhases), restored_scene.hooks(), false);
    std::istringstream in(saved.str());
    restored.read_checkpoint(in);
    EXPECT_EQ(restored_scene.handed, 1);
    EXPECT_EQ(restored_scene.starts[1], 1.75);
    EXPECT_TRUE(std::isinf(restored_scene.starts[2]));
    std::vector<std::string> none;
    restored.take_events(none);
    EXPECT_TRUE(none.empty());
    std::vector<io::ResultFigure> no_results;
    restored.append_results(no_results);
    EXPECT_TRUE(no_results.empty()) << "a standalone settle watch reports instead";
}

} // namespace
} // namespace grainload::particles
