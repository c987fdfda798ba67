#pragma once
// The particles sources create and sinks take over a run, and the step while sand flows.

#include "app/resources/step_plan.hpp"
#include "io/types.hpp"

namespace grainload::sph {
class SphModel;
}

namespace grainload::app {

/// The particles the sources create, averaged over the run [0, end]: each source creates
/// mass_rate (end - start) / particle mass particles (at most its lattice's sites) at an even
/// rate, and one created at t is there for end - t. (What the sinks take is
/// average_discharged's.)
double average_created(const sph::SphModel& sph, double end);

/// The particles the sinks with a declared outlet ([[sph.sink]] outlet_width) take, averaged
/// over the run [0, end]: at Beverloo's rate from the opening (the first wall removed at a
/// stated time; t = 0 when no wall is due to go) until the material there and to come is
/// gone. A wall due to go at the start of a phase opens at the earliest that phase can start:
/// the latest stated end of the phases before it (a phase that ends on a condition ends no
/// earlier than it began; the CI hopper's settle took 0.15 s after its 1 s fill).
/// A wall due to go on [sph.settle] has no time yet: then `known` is false and nothing is
/// taken (the estimate stays an upper bound).
struct Discharge {
    double average = 0.0; ///< particles taken, averaged over the run
    double rate = 0.0;    ///< the outlets' Beverloo rate, kg/s (kg/m/s in plane strain)
    double opening = 0.0;
    double emptied = 0.0;  ///< when the material present and to come has gone (inf: never)
    bool declared = false; ///< a sink with an outlet
    bool known = true;     ///< the opening time is known before the run
    bool earliest = false; ///< the opening is a phase's earliest start
};
Discharge average_discharged(const sph::SphModel& sph, double end);

/// The SPH step over the run: the stable step at t = 0, `rest`, and while the outlets of
/// `discharge` flow (from its opening until it has emptied or the run ends) the CFL step
/// C h / (c + v) at the speed v of the fastest grain, the returned `speed`: one leaving the
/// outlet at Beverloo's mean velocity W / (rho_b A) and falling freely from the material's
/// lowest point at t = 0 (where the outlet is) to the sink's plane, sqrt(v0^2 + 2 g d). No
/// change for a fixed step, an unknown opening or a sink that is not a plane below the
/// material.
struct FlowStep {
    StepProfile profile;
    double speed = 0.0;
};
FlowStep flow_step(const sph::SphModel& sph, const Discharge& discharge, const Vec3& gravity,
                   double end);

} // namespace grainload::app
