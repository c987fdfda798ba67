#include "sph/keyword_body_reader.hpp"

#include "io/case_table.hpp"
#include "io/deck_ledger.hpp"
#include "io/keyword_deck.hpp"
#include "io/keyword_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace grainload::sph {

namespace {

io::KeywordMesh read_deck(const io::CaseTable& shape) {
    std::string error;
    const auto units = io::parse_keyword_units(shape.string("units"), &error);
    if (!units) {
        shape.fail("units", error);
    }
    const std::string path = shape.file_path("file");
    io::open_keyword_deck(shape, path, *units);
    try {
        io::KeywordMesh deck = io::read_keyword_mesh(io::read_keyword_deck(path), *units);
        shape.deck_ledger().leave(path, deck.ignored);
        return deck;
    } catch (const std::invalid_argument& e) {
        shape.fail("file", e.what());
    }
}

/// Refuses particles whose deck mass (or volume) is off density * spacing^d (spacing^d).
void check_masses(const io::CaseTable& shape, const std::vector<const io::KeywordParticle*>& list,
                  double spacing, int dimension, double density) {
    const double tolerance =
        shape.number_or("mass_tolerance", io::default_value(kKeywordBodyKeys, "mass_tolerance"));
    if (!(tolerance > 0.0)) {
        shape.fail("mass_tolerance", "expected a relative tolerance > 0");
    }
    const double volume = std::pow(spacing, dimension);
    const io::KeywordParticle* first = nullptr;
    double first_expected = 0.0;
    std::size_t count = 0;
    for (const io::KeywordParticle* p : list) {
        const double expected = p->is_volume ? volume : density * volume;
        if (p->mass != 0.0 && std::abs(p->mass - expected) > tolerance * expected) {
            first = first ? first : p;
            first_expected = first == p ? expected : first_expected;
            ++count;
        }
    }
    if (first != nullptr) {
        std::ostringstream message;
        message << first->source.text() << ": *ELEMENT_SPH particle " << first->node << " has the "
                << (first->is_volume ? "volume " : "mass ") << first->mass
                << (first->is_volume ? " m^3, the body's spacing^d is "
                                     : " kg, the body's "
                                       "density * spacing^d is ")
                << first_expected << "; " << count << " of " << list.size()
                << " particles differ by more than mass_tolerance = " << tolerance;
        shape.fail("file", message.str());
    }
}

} // namespace

std::vector<Vec3> read_keyword_particles(const io::CaseTable& shape, double spacing, int dimension,
                                         double density) {
    const io::KeywordMesh deck = read_deck(shape);
    std::vector<io::KeywordId> with_particles;
    for (const io::KeywordParticle& p : deck.particles) {
        with_particles.push_back(p.part);
    }
    std::sort(with_particles.begin(), with_particles.end());
    with_particles.erase(std::unique(with_particles.begin(), with_particles.end()),
                         with_particles.end());
    std::vector<io::KeywordId> parts;
    try {
        parts = io::select_parts(
            deck, shape.has("parts") ? shape.name_list("parts") : std::vector<std::string>{},
            with_particles, "SPH", shape.string("file"));
    } catch (const std::invalid_argument& e) {
        shape.fail(shape.has("parts") ? "parts" : "file", e.what());
    }
    const std::set<io::KeywordId> selected(parts.begin(), parts.end());
    std::vector<const io::KeywordParticle*> chosen;
    std::vector<Vec3> points;
    for (const io::KeywordParticle& p : deck.particles) {
        if (!selected.contains(p.part)) {
            continue;
        }
        try {
            points.push_back(deck.nodes[deck.node(p.node, p.source.text() + ": *ELEMENT_SPH")]);
        } catch (const std::invalid_argument& e) {
            shape.fail("file", e.what());
        }
        if (dimension == 2 && points.back().z() != 0.0) {
            shape.fail("file", p.source.text() + ": *ELEMENT_SPH particle " +
                                   std::to_string(p.node) + " lies off z = 0 in a 2D case");
        }
        chosen.push_back(&p);
    }
    check_masses(shape, chosen, spacing, dimension, density);
    return points;
}

} // namespace grainload::sph
