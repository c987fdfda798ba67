#include "sph/energy_ledger.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace grainload::sph {
namespace {

// Hand-worked books: held 10 J, 2 J in initial stresses, 3 J in the contact potential at t = 0;
// gravity puts in 5 J, the walls take 1 J out and later give 0.5 J back.
EnergyLedger worked_example() {
    EnergyLedger ledger;
    ledger.open(10.0, 2.0, 3.0);
    ledger.add_gravity_work(5.0);
    ledger.add_wall_work(-1.0);
    ledger.add_wall_work(0.5);
    return ledger;
}

TEST(EnergyLedger, BooksWorkAndScalesByTheLargestWorkSoFar) {
    const EnergyLedger ledger = worked_example();
    EXPECT_DOUBLE_EQ(ledger.gravity_work(), 5.0);
    EXPECT_DOUBLE_EQ(ledger.wall_work(), -0.5);
    // 10 + 2 + 3 at t = 0, 5 from gravity, and the walls' largest |work| so far, 1 (not 0.5).
    EXPECT_DOUBLE_EQ(ledger.throughput(), 21.0);
    // Held 14 J: 10 + 5 - 0.5 = 14.5 expected, 0.5 J short.
    EXPECT_DOUBLE_EQ(ledger.surplus(14.0), -0.5);
    // With 2 J now in the contact potential (3 J at t = 0): (14 + 2 - 10 - 3 - 4.5) / 21.
    EXPECT_DOUBLE_EQ(ledger.balance_error(14.0, 2.0), -1.5 / 21.0);
}

TEST(EnergyLedger, DiagnosesASurplusAboveTheLimitOnly) {
    const EnergyLedger ledger = worked_example();
    // Surplus 21 J = 1.0 times the throughput: not above it.
    EXPECT_FALSE(ledger.check(14.5 + 21.0, 1.0).has_value());
    const auto problem = ledger.check(14.5 + 21.1, 1.0);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("energy is being created"), std::string::npos) << *problem;
    EXPECT_FALSE(EnergyLedger().check(1e9, 1.0).has_value()) << "a ledger not opened";
}

// Particles leaving take 3 J of kinetic + internal energy and release 0.5 J of contact
// potential: booked as removed, neither shows as a deficit, and the checkpoint state keeps them.
TEST(EnergyLedger, RemovedParticlesAreNoDeficit) {
    EnergyLedger ledger = worked_example();
    const double surplus_before = ledger.surplus(14.0);
    const double error_before = ledger.balance_error(14.0, 2.0);
    ledger.add_removed(3.0, 0.5);
    EXPECT_DOUBLE_EQ(ledger.surplus(11.0), surplus_before);
    EXPECT_DOUBLE_EQ(ledger.balance_error(11.0, 1.5), error_before);
    EnergyLedger restored;
    restored.set_state(ledger.state());
    EXPECT_DOUBLE_EQ(restored.removed_held(), 3.0);
    EXPECT_DOUBLE_EQ(restored.removed_contact(), 0.5);
}

// Particles entering with 4 J of kinetic energy and 0.5 J of contact potential with what is
// there: held rises by 4 J and the contact potential by 0.5 J at once, so booked as created
// they leave the surplus and the balance where they were; the throughput grows by 4.5 J.
TEST(EnergyLedger, CreatedParticlesBringWhatTheyHoldWithoutASurplus) {
    EnergyLedger ledger = worked_example();
    const double surplus_before = ledger.surplus(14.0);
    const double error_before = ledger.balance_error(14.0, 2.0);
    const double throughput_before = ledger.throughput();
    ledger.add_created(4.0, 0.5);
    EXPECT_DOUBLE_EQ(ledger.surplus(18.0), surplus_before);
    EXPECT_DOUBLE_EQ(ledger.balance_error(18.0, 2.5) * ledger.throughput(),
                     error_before * throughput_before);
    EXPECT_DOUBLE_EQ(ledger.throughput(), throughput_before + 4.5);
    EnergyLedger restored;
    restored.set_state(ledger.state());
    EXPECT_DOUBLE_EQ(restored.created_held(), 4.0);
    EXPECT_DOUBLE_EQ(restored.created_contact(), 0.5);
}

// One removed particle with a NaN internal energy (the elastic hopper wagon's, a NaN wall
// damping heat) makes removed_energy and the balance NaN for the rest of the run. The books
// name that entry, for summary.json and for the watchdog, whose surplus test (NaN > limit is
// false) let it pass before; an infinite held energy is named as the particles'.
TEST(EnergyLedger, NamesANonFiniteEntryAndTheWatchdogStopsOnIt) {
    EnergyLedger ledger = worked_example();
    EXPECT_FALSE(ledger.non_finite(14.0, 2.0).has_value());
    ledger.add_removed(std::numeric_limits<double>::quiet_NaN(), 0.5);
    EXPECT_TRUE(std::isnan(ledger.balance_error(11.0, 1.5)));
    const auto named = ledger.non_finite(11.0, 1.5);
    ASSERT_TRUE(named.has_value());
    EXPECT_EQ(named->rfind("removed_energy is nan J", 0), 0u) << *named;
    const auto problem = ledger.check(11.0, 1.0);
    ASSERT_TRUE(problem.has_value()) << "a NaN surplus passed the watchdog";
    EXPECT_NE(problem->find("not finite (removed_energy"), std::string::npos) << *problem;
    const auto held = worked_example().check(std::numeric_limits<double>::infinity(), 1.0);
    ASSERT_TRUE(held.has_value());
    EXPECT_NE(held->find("kinetic_energy + internal_energy is inf J"), std::string::npos) << *held;
}

TEST(EnergyLedger, StateRoundTripsAndRejectsAForeignLayout) {
    const EnergyLedger ledger = worked_example();
    EnergyLedger restored;
    restored.set_state(ledger.state());
    EXPECT_DOUBLE_EQ(restored.throughput(), ledger.throughput());
    EXPECT_DOUBLE_EQ(restored.balance_error(14.0, 2.0), ledger.balance_error(14.0, 2.0));
    EXPECT_THROW(restored.set_state({1.0, 2.0}), std::runtime_error);
}

} // namespace
} // namespace grainload::sph
