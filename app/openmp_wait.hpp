#pragma once

namespace grainload::app {

/// The product default of OpenMP waiting: a thread that reaches the end of a parallel loop
/// first spins GOMP_SPINCOUNT = 1000 times (about 0.1 ms on the 2-core VMs this was measured
/// on, where a PAUSE takes 92 ns) and then sleeps. libgomp's own default, 300 000 spins (27 ms
/// there), made two threads 10-14x slower when other processes held a core: the thread with
/// the work waited for the core while its partner spun. Sleeping at once
/// (OMP_WAIT_POLICY=passive) costs a futex wake-up at each of the dozen parallel loops of a
/// step on a quiet machine. An explicit OMP_WAIT_POLICY or GOMP_SPINCOUNT wins.
///
/// libgomp reads both when it loads, before main, so this puts the default into the
/// environment and runs the program again, once (/proc/self/exe, Linux); call it first thing
/// in main. If the exec fails the program runs on with libgomp's default.
void default_openmp_wait(char** argv);

} // namespace grainload::app
