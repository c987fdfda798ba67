#pragma once
// The watch for material particles that leave the scene faster than any sound run lets them.

#include "sph/particle_set.hpp"

#include <functional>
#include <optional>
#include <string>

namespace grainload::sph {

/// Margin of the scene box on every side, as a fraction of the box's largest extent: room for
/// sand that spills over an edge or bounces, so that only a particle far from everything the
/// case set up can be taken for escaping.
inline constexpr double kEscapeMarginFraction = 0.5;

/// The watchdog's speed factor: a particle outside the box is escaping when it moves outward
/// faster than kEscapeSpeedFactor * sqrt(v0^2 + 2 g (H + d)). The root is the speed of a
/// particle that started with the scene's largest speed v0 and fell freely from the top of the
/// box (largest extent H) to its distance d outside the box: energy conservation bounds every
/// sound particle by it, up to what contacts and pressure pass between particles. A factor 2
/// (4 times the specific energy) leaves room for that, and an instability, which grows
/// exponentially, passes any fixed factor within a few steps of becoming visible.
inline constexpr double kEscapeSpeedFactor = 2.0;

/// Watches for material particles that leave the scene at a speed no sound run gives them:
/// the scene box is the bounding box of every particle (bodies and walls) at the start,
/// widened by kEscapeMarginFraction of its largest extent, and grown by where the walls are
/// now (a wall moved by its motion or by a shell takes its sand with it); v0 is the largest
/// speed of any particle at the start or of any wall particle now.
class EscapeWatch {
  public:
    /// Watches nothing.
    EscapeWatch() = default;
    EscapeWatch(const ParticleSet& particles, const Vec3& gravity, int dimension);

    /// A one-line diagnosis for the first material particle (in index order) outside the box
    /// moving outward faster than the limit, naming it, its body (`body_name` of its body id),
    /// its distance and speed; std::nullopt when there is none.
    std::optional<std::string>
    check(const ParticleSet& particles,
          const std::function<std::string(int body_id)>& body_name) const;

  private:
    /// The scene box now (the start's, widened by the walls where they are) with its height,
    /// and the fastest speed a particle may have without falling: the walls' fastest or the
    /// start's.
    struct Reach {
        Vec3 lower = Vec3::Zero();
        Vec3 upper = Vec3::Zero();
        double height = 0.0;
        double v0 = 0.0;
    };
    Reach reach_now(const ParticleSet& particles) const;

    bool active_ = false;
    int dimension_ = 3;
    Vec3 lower_ = Vec3::Zero();
    Vec3 upper_ = Vec3::Zero();
    double margin_ = 0.0;
    double gravity_ = 0.0;
    double initial_speed_ = 0.0;
};

} // namespace grainload::sph
