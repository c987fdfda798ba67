#pragma once
// Wall-load maps: the normal pressure and friction traction of chosen walls, binned on a grid
// (SPH's and the DEM's).

#include "io/frame.hpp"
#include "io/types.hpp"
#include "particles/scene_part.hpp"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::particles {

/// A load on a mapped wall in a step: where it acts, the wall's normal there (into the
/// material) and the force the material puts on the wall there.
struct WallLoad {
    Vec3 at = Vec3::Zero();
    Vec3 normal = Vec3::Zero();
    Vec3 force = Vec3::Zero();
};

/// The loads on the method's wall `wall` (an index of its walls) in the step just made, in an
/// order that does not depend on the thread count.
using WallLoads = std::function<void(int wall, std::vector<WallLoad>& loads)>;

/// Wall loads the way engineers read them: the normal pressure and the wall-friction
/// traction of chosen walls, binned on a grid, as the mean over each output interval and as the
/// mean and maximum over a time window. A cylinder is unrolled (axial position x angle). The
/// force of the bodies on a wall particle (mass x acceleration after the force pass,
/// accumulate_wall_load) is split by the wall's normal n there (into the material):
///   pressure p = -f . n / A,   traction t = (f - (f . n) n) / A,
/// A the cell's area; t is given along the axis and around it (cylinder) or along the grid's
/// edges (plane). The impulses f dt of every step are summed per cell, so a map is the mean
/// over its interval, not a snapshot of one step's noise. The method gives the loads: SPH the
/// force on each wall particle, standing for a patch of its spacing; the DEM each contact's
/// force on a wall, at its point.
class WallMapSet {
  public:
    /// Loads of one cell: pressure and two traction components, in Pa (N/m in plane strain
    /// per metre of depth: the particles' masses are per metre, so are the areas).
    using Load = std::array<double, 3>;

    struct Map {
        std::string name;
        std::vector<int> walls; ///< indices into the method's walls
        bool cylinder = true;
        Vec3 origin = Vec3::Zero();
        Vec3 axis = Vec3::UnitZ();      ///< cylinder: unit axis
        Vec3 reference = Vec3::UnitX(); ///< cylinder: unit direction of angle 0
        double radius = 0.0;
        double length = 0.0;
        double angle_start = 0.0;
        double angle_end = 0.0;
        Vec3 edge_u = Vec3::Zero();
        Vec3 edge_v = Vec3::Zero(); ///< plane strain: zero (1 m of depth)
        int bins_1 = 1;             ///< along the axis, or along edge_u
        int bins_2 = 1;             ///< around the axis, or along edge_v
        double reach = 0.0;         ///< infinity: no limit
        /// Half the width of the patch each load on one of `walls` stands for: SPH's particle
        /// load is spread over the patch of one spacing around it (see shares()); 0 for a
        /// point (a DEM contact), whose load goes to the cell that holds it.
        std::vector<double> half_spacing;
        double window_start = 0.0;
        double window_end = 0.0;
        // State (checkpointed): impulses of the current interval and of the window per cell,
        // the window's maximum of the interval means.
        std::vector<Load> interval;
        std::vector<Load> window_sum;
        std::vector<Load> window_max;
        bool window_seen = false; ///< an interval mean has entered window_max

        int cells() const { return bins_1 * bins_2; }
        double cell_area() const;
        /// Grid coordinates of x, each 0 to 1 across the grid (outside: beyond it), or nullopt
        /// beyond reach of the surface.
        std::optional<std::array<double, 2>> coordinates(const Vec3& x) const;
        /// The cells a load at x shares with, and the shares (they sum to 1): its patch, `half`
        /// either side, against the cells (a point: the cell holding it); 0 outside the grid or
        /// beyond reach.
        int shares(const Vec3& x, double half, std::array<std::pair<int, double>, 4>& out) const;
        /// The grid's size along its two directions (m; 0: plane strain's depth).
        std::array<double, 2> extents() const;
        /// A full circle: the angle wraps around.
        bool periodic() const;
        /// The load of force f on a wall point x with normal n (into the material), per area.
        Load split(const Vec3& x, const Vec3& n, const Vec3& f) const;
        /// Cell centre coordinates: axial position (m) and angle (deg), or u and v (m).
        std::array<double, 2> centre(int cell) const;
    };

    WallMapSet() = default;
    /// The maps as particles/wall_map_reader.hpp reads them from a case.
    explicit WallMapSet(std::vector<Map> maps) : maps_(std::move(maps)) { reset(); }

    bool empty() const { return maps_.empty(); }
    const std::vector<Map>& maps() const { return maps_; }

    /// Add the impulses of the step [t, t + dt], its loads as `loads` gives them.
    void accumulate(double t, double dt, const WallLoads& loads);
    /// At an output instant: DIR/wall_maps/NAME_NNNNNN.csv (the mean over the interval since
    /// the last instant; zeros at the first) and NAME_window.csv, written atomically.
    void record(double time, const std::string& directory);
    /// Per map: the window's largest mean and maximum pressure and where, and its mean pressure
    /// and traction resultants.
    void append_results(std::vector<io::ResultFigure>& results) const;

    /// For checkpoints: every map's sums, the interval clock and the instant count.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    void reset();
    void write_interval(const Map& map, double time, double length,
                        const std::string& directory) const;
    void write_window(const Map& map, const std::string& directory) const;
    /// Mean over the window so far: its impulse over the elapsed part of the window.
    Load window_mean(const Map& map, int cell) const;

    /// One load's cells, shares and split in a step (scratch of accumulate()).
    struct ParticleShares {
        int count = 0;
        std::array<std::pair<int, double>, 4> cells;
        Load load{};
    };

    std::vector<Map> maps_;
    std::vector<ParticleShares> shares_;
    std::vector<WallLoad> loads_;
    double last_time_ = 0.0;    ///< the last instant recorded
    double instants_ = 0.0;     ///< files written per map so far (a count; double for state())
    bool recorded_any_ = false; ///< an instant has been recorded
};

/// The maps as a scene part named `name` (its checkpoint section: "sph.wall_map", "dem.wall_map"):
/// they sum the loads `loads` gives after every step and write their interval and window tables
/// at the output instants.
std::unique_ptr<ScenePart> wall_map_part(std::string name, WallMapSet maps, WallLoads loads);

} // namespace grainload::particles
