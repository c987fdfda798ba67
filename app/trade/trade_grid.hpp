#pragma once
// The grid of a grainload trade sweep: axes of case-key values and the runs they make.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::app {

/// One axis of a `grainload trade` sweep: a case key (dotted, as --set takes it) and its values,
/// plus keys that move with it (--link: one value per value of the axis, e.g. the wall spacing
/// and the column's placement that follow the particle spacing).
struct TradeAxis {
    std::string key;
    std::vector<std::string> values; ///< each a --set value ("10 mm", 0.1, "\"quintic\"")
    std::vector<TradeAxis> linked;
    /// --reference KEY=VALUE: the axis' most accurate value, overriding its rule.
    std::optional<std::string> reference;
};

/// One run of the grid: which value of each axis, its --set overrides and its directory name.
struct TradeRun {
    std::string id;
    std::vector<std::size_t> index;     ///< value index per axis
    std::vector<std::string> overrides; ///< "key=value", each axis then its linked keys
};

/// "KEY=V1,V2,..." of --vary or --link. Values are split at commas outside quotes and brackets
/// ("[1, 2]" stays one value); blanks around them are trimmed; an empty value, a repeated value
/// or a missing '=' is refused. `option` names the flag in messages. Throws io::CaseError.
TradeAxis parse_trade_axis(std::string_view text, std::string_view option);

/// Adds `--link` axis `link` to the last --vary axis; refused without one or with a different
/// number of values.
void link_trade_axis(std::vector<TradeAxis>& axes, TradeAxis link);

/// Applies `--reference KEY=VALUE` to the axis of that key; refused for a key that is no axis
/// or a value that is not one of its values.
void set_trade_reference(std::vector<TradeAxis>& axes, std::string_view text);

/// The Cartesian product of the axes, the first axis slowest. A run's id joins, for each axis,
/// the key's last name and its value ("spacing_7.2mm-stiffness_scale_0.01"), characters other
/// than letters, digits, '.', '+' and '-' dropped or replaced, so that a grid extended later
/// keeps the ids (and finished runs) of the old one.
std::vector<TradeRun> trade_grid(const std::vector<TradeAxis>& axes);

/// How an axis' most accurate value is chosen, by the key's last name:
///   spacing, cfl_safety, time_step, window, iteration_tolerance: the smallest;
///   stiffness_scale: the closest to 1 (|ln s| smallest);
///   max_subcycles: the smallest positive one (0 is "no limit", the least accurate);
///   max_iterations: the largest;
/// any other key (kernel, smoothing_length_ratio, alpha, ...) has no rule and needs --reference.
enum class AccuracyRule { smallest, closest_to_one, smallest_limit, largest, none };
AccuracyRule accuracy_rule(std::string_view key);
std::string describe(AccuracyRule rule);

/// Per axis, the index of its most accurate value: --reference, or the rule applied to the
/// values read as quantities ("7.2 mm", 0.3). Throws io::CaseError naming the axis when it has
/// no rule and no --reference, or when its values are not comparable quantities.
std::vector<std::size_t> most_accurate(const std::vector<TradeAxis>& axes);

/// The run of `grid` whose indices are `best`.
std::size_t find_run(const std::vector<TradeRun>& grid, const std::vector<std::size_t>& best);

/// Relative step of gravity between the members of a round-off ensemble (--noise): far below
/// any physical effect (a figure that follows gravity smoothly moves by about this much), far
/// above the 1e-16 of double round-off, so that a chaotic figure (a granular residue decided
/// grain by grain) decorrelates within the run.
inline constexpr double kNoiseGravityStep = 1e-8;

/// The members 1 .. members-1 of the round-off ensemble of `best` (member 0 is `best` itself):
/// its overrides plus `case.gravity` scaled by 1 + d_k, d_k = +1, -1, +2, -2, ... times
/// kNoiseGravityStep; ids "<best id>-noise_<k>". `gravity` is the case's (after the overrides)
/// in m/s^2, written with `dimension` components.
std::vector<TradeRun> noise_runs(const TradeRun& best, const std::array<double, 3>& gravity,
                                 int dimension, int members);

} // namespace grainload::app
