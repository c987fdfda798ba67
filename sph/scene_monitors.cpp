#include "sph/scene_monitors.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"

#include <utility>

namespace grainload::sph {

namespace {

class WallMapPart final : public particles::ScenePart {
  public:
    WallMapPart(WallMapSet maps, const ParticleSet& particles, const std::vector<Wall>& walls)
        : maps_(std::move(maps)), particles_(&particles), walls_(&walls) {}
    std::string_view name() const override { return "sph.wall_map"; }
    void after_step(double t, double dt) override { maps_.accumulate(*particles_, *walls_, t, dt); }
    void at_output(double time, io::OutputStreams& output) override {
        maps_.record(time, output.directory());
    }
    void append_results(std::vector<io::ResultFigure>& results) const override {
        maps_.append_results(results);
    }
    void write_checkpoint(std::ostream& out) const override { io::write_array(out, maps_.state()); }
    void read_checkpoint(std::istream& in) override {
        std::vector<double> state;
        io::read_array(in, state);
        maps_.set_state(state);
    }

  private:
    WallMapSet maps_;
    const ParticleSet* particles_;
    const std::vector<Wall>* walls_;
};

class HeapPart final : public particles::ScenePart {
  public:
    HeapPart(HeapMonitor heap, const ParticleSet& particles)
        : heap_(std::move(heap)), particles_(&particles) {}
    std::string_view name() const override { return "sph.heap"; }
    void end_step(double time) override { heap_.record(time, *particles_); }
    void append_results(std::vector<io::ResultFigure>& results) const override {
        heap_.append_results(*particles_, results);
    }
    void write_checkpoint(std::ostream& out) const override { io::write_array(out, heap_.state()); }
    void read_checkpoint(std::istream& in) override {
        std::vector<double> state;
        io::read_array(in, state);
        heap_.set_state(state);
    }

  private:
    HeapMonitor heap_;
    const ParticleSet* particles_;
};

class EscapePart final : public particles::ScenePart {
  public:
    EscapePart(EscapeWatch watch, const ParticleSet& particles,
               std::function<std::string(int body_id)> body_name)
        : watch_(std::move(watch)), particles_(&particles), body_name_(std::move(body_name)) {}
    std::string_view name() const override { return "sph.escape_watch"; }
    std::optional<std::string> diagnose() const override {
        return watch_.check(*particles_, body_name_);
    }

  private:
    EscapeWatch watch_;
    const ParticleSet* particles_;
    std::function<std::string(int body_id)> body_name_;
};

} // namespace

std::unique_ptr<particles::ScenePart> wall_map_part(WallMapSet maps, const ParticleSet& particles,
                                                    const std::vector<Wall>& walls) {
    return std::make_unique<WallMapPart>(std::move(maps), particles, walls);
}

std::unique_ptr<particles::ScenePart> heap_part(HeapMonitor heap, const ParticleSet& particles) {
    return std::make_unique<HeapPart>(std::move(heap), particles);
}

std::unique_ptr<particles::ScenePart>
escape_part(EscapeWatch watch, const ParticleSet& particles,
            std::function<std::string(int body_id)> body_name) {
    return std::make_unique<EscapePart>(std::move(watch), particles, std::move(body_name));
}

} // namespace grainload::sph
