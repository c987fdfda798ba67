#include "particles/scene_part_list.hpp"

#include "io/binary_stream.hpp"

#include <cstdint>
#include <stdexcept>

namespace grainload::particles {

void ScenePartList::after_step(double t, double dt) {
    for (const auto& part : parts_) {
        part->after_step(t, dt);
    }
}

void ScenePartList::end_step(double time) {
    for (const auto& part : parts_) {
        part->end_step(time);
    }
}

Index ScenePartList::collect_departures(const ParticleView& particles, double time,
                                        std::vector<char>& gone) {
    Index count = 0;
    for (const auto& part : parts_) {
        count += part->collect_departures(particles, time, gone);
    }
    return count;
}

void ScenePartList::after_removal(std::span<const Index> new_index) {
    for (const auto& part : parts_) {
        part->after_removal(new_index);
    }
}

std::vector<Arrival> ScenePartList::collect_arrivals(const ParticleView& particles, double t,
                                                     double dt) {
    std::vector<Arrival> arrivals;
    for (const auto& part : parts_) {
        part->collect_arrivals(particles, t, dt, arrivals);
    }
    return arrivals;
}

void ScenePartList::at_output(double time, io::OutputStreams& output) {
    for (const auto& part : parts_) {
        part->at_output(time, output);
    }
}

void ScenePartList::append_results(std::vector<io::ResultFigure>& results) const {
    for (const auto& part : parts_) {
        part->append_results(results);
    }
}

std::vector<std::string> ScenePartList::take_events() {
    std::vector<std::string> events;
    for (const auto& part : parts_) {
        part->take_events(events);
    }
    return events;
}

std::optional<std::string> ScenePartList::diagnose() const {
    for (const auto& part : parts_) {
        if (auto diagnosis = part->diagnose()) {
            return diagnosis;
        }
    }
    return std::nullopt;
}

void ScenePartList::write_checkpoint(std::ostream& out) const {
    io::write_value(out, static_cast<std::uint64_t>(parts_.size()));
    for (const auto& part : parts_) {
        io::write_string(out, std::string(part->name()));
        part->write_checkpoint(out);
    }
}

void ScenePartList::read_checkpoint(std::istream& in) {
    const auto count = io::read_value<std::uint64_t>(in);
    if (count != parts_.size()) {
        throw std::runtime_error("checkpoint: it holds the state of " + std::to_string(count) +
                                 " scene parts, the case builds " + std::to_string(parts_.size()));
    }
    for (const auto& part : parts_) {
        const std::string name = io::read_string(in);
        if (name != part->name()) {
            throw std::runtime_error("checkpoint: expected the state of the scene part " +
                                     std::string(part->name()) + ", found " + name);
        }
        part->read_checkpoint(in);
    }
}

} // namespace grainload::particles
