// `--threads auto`: the busy cores between two /proc/stat samples, counted from hand-made
// samples whose busy fractions are known, and the parser on the layout proc(5) documents; the
// OpenMP waiting it chooses and the count it hands to the program run again.

#include "app/resources/openmp_wait.hpp"
#include "app/resources/thread_count.hpp"

#include <cstdlib>
#include <gtest/gtest.h>
#include <sstream>

namespace {

using grainload::app::CpuTicks;
using grainload::app::free_cores;
using grainload::app::parse_cpu_ticks;

TEST(ThreadCount, ParsesThePerCpuLinesOfProcStat) {
    // user nice system idle iowait irq softirq steal guest guest_nice: busy = all but idle and
    // iowait; guest time is already inside user (proc(5)), so the first eight fields count.
    std::istringstream stat("cpu  30 0 10 200 5 0 0 0 0 0\n"
                            "cpu0 20 0 5 100 2 1 1 0 7 0\n"
                            "cpu1 10 0 5 100 3 0 0 2 0 0\n"
                            "intr 12345 0 0\n"
                            "ctxt 999\n");
    const auto cpus = parse_cpu_ticks(stat);
    ASSERT_EQ(cpus.size(), 2u);
    EXPECT_EQ(cpus[0].busy, 27u);   // 20 + 5 + 1 + 1
    EXPECT_EQ(cpus[0].total, 129u); // + 100 idle + 2 iowait
    EXPECT_EQ(cpus[1].busy, 17u);   // 10 + 5 + 2 steal
    EXPECT_EQ(cpus[1].total, 120u);
    std::istringstream empty("intr 1\n");
    EXPECT_TRUE(parse_cpu_ticks(empty).empty());
}

TEST(ThreadCount, FreeCoresAreTheCpusLessTheBusyOnes) {
    const std::vector<CpuTicks> start{{1000, 5000}, {2000, 6000}};
    // Another process holds CPU 1 for all 20 ticks of the sample, CPU 0 idles: one core free.
    EXPECT_EQ(free_cores(start, {{1000, 5020}, {2020, 6020}}), 1);
    // Background noise of 3 and 4 ticks in 20 (0.35 core): both free.
    EXPECT_EQ(free_cores(start, {{1003, 5020}, {2004, 6020}}), 2);
    // Two busy halves make one busy core: one free.
    EXPECT_EQ(free_cores(start, {{1010, 5020}, {2010, 6020}}), 1);
    // Of the busy core, 0.6 was this process's own threads (a library's spinning pool): the
    // other work is 0.4 core, both free.
    EXPECT_EQ(free_cores(start, {{1000, 5020}, {2020, 6020}}, 0.6), 2);
    // Everything busy: still one thread.
    EXPECT_EQ(free_cores(start, {{1020, 5020}, {2020, 6020}}), 1);
    // Samples that cannot be compared (a CPU came online): the CPU count.
    EXPECT_EQ(free_cores(start, {{1020, 5020}, {2020, 6020}, {0, 10}}), 3);
    EXPECT_EQ(free_cores({}, {}), 1);
}

// The spin count follows the threads `auto` found free: long spins only where both cores were
// free (docs/performance.md measured both on a quiet and a loaded machine).
TEST(ThreadCount, AutoOnAQuietMachineSpinsLongerThanTheDefault) {
    char run[] = "grainload";
    char command[] = "run";
    char option[] = "--threads";
    char automatic[] = "auto";
    char two[] = "2";
    char* asks[] = {run, command, option, automatic, nullptr};
    char* fixed[] = {run, command, option, two, nullptr};
    char* dangling[] = {run, command, option, nullptr};
    EXPECT_TRUE(grainload::app::asks_auto_threads(asks));
    EXPECT_FALSE(grainload::app::asks_auto_threads(fixed));
    EXPECT_FALSE(grainload::app::asks_auto_threads(dangling));
    EXPECT_EQ(grainload::app::spin_count_for(1), grainload::app::kSharedSpinCount);
    EXPECT_EQ(grainload::app::spin_count_for(2), grainload::app::kQuietSpinCount);
    EXPECT_LT(std::stoi(std::string(grainload::app::kSharedSpinCount)),
              std::stoi(std::string(grainload::app::kQuietSpinCount)));
}

// The count handed through the environment is taken only when it is a positive integer; any
// other text means "measure again".
TEST(ThreadCount, HandedCountIsAPositiveIntegerOrNothing) {
    const char* name = grainload::app::kAutoThreadsVariable;
    unsetenv(name);
    EXPECT_FALSE(grainload::app::handed_auto_threads().has_value());
    setenv(name, "3", 1);
    EXPECT_EQ(grainload::app::handed_auto_threads(), 3);
    for (const char* bad : {"0", "-1", "two", "2x", ""}) {
        setenv(name, bad, 1);
        EXPECT_FALSE(grainload::app::handed_auto_threads().has_value()) << bad;
    }
    unsetenv(name);
}

} // namespace
