#include "fem/shell_directors.hpp"

#include "fem/dof_index.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::fem {

namespace {

/// Distinct corners of an element: three for a triangle (its fourth node repeats the third).
int corner_count(const ShellElement& element) {
    return element.is_triangle() ? 3 : 4;
}

/// Elements around every node, each listed once.
std::vector<std::vector<Index>> elements_around(const ShellMesh& mesh) {
    std::vector<std::vector<Index>> around(at(mesh.node_count()));
    for (Index e = 0; e < mesh.element_count(); ++e) {
        const ShellElement& element = mesh.element(e);
        for (int k = 0; k < corner_count(element); ++k) {
            around[at(element.nodes[at(k)])].push_back(e);
        }
    }
    return around;
}

std::vector<Vec3> element_normals(const ShellMesh& mesh) {
    std::vector<Vec3> normals;
    normals.reserve(at(mesh.element_count()));
    for (const ShellElement& element : mesh.elements()) {
        normals.push_back(element_normal(mesh, element));
    }
    return normals;
}

/// The fold test of one node: some element normal more than the fold angle away from the
/// average normal. Comparing with the average (not pairwise, as Abaqus does) keeps coarse
/// smooth meshes smooth: two elements 22.5 deg apart deviate 11.25 deg from their average.
bool is_fold(const std::vector<Index>& around, const std::vector<Vec3>& normals, double cos_fold) {
    Vec3 sum = Vec3::Zero();
    for (const Index e : around) {
        sum += normals[at(e)];
    }
    const double length = sum.norm();
    if (length <= 1e-12 * static_cast<double>(around.size())) {
        return !around.empty();
    }
    const Vec3 average = sum / length;
    return std::any_of(around.begin(), around.end(),
                       [&](Index e) { return normals[at(e)].dot(average) < cos_fold; });
}

/// Director of element `e` at a fold node: average of the normals within the fold angle of
/// its own (its own face on a fold between flat faces).
Vec3 fold_director(Index e, const std::vector<Index>& around, const std::vector<Vec3>& normals,
                   double cos_fold) {
    const Vec3& own = normals[at(e)];
    Vec3 sum = Vec3::Zero();
    for (const Index f : around) {
        if (normals[at(f)].dot(own) >= cos_fold) {
            sum += normals[at(f)];
        }
    }
    return sum.normalized();
}

} // namespace

std::vector<Index> fold_nodes(const ShellMesh& mesh) {
    std::vector<Index> folds;
    const double cos_fold = std::cos(mesh.fold_angle());
    const std::vector<Vec3> normals = element_normals(mesh);
    const std::vector<std::vector<Index>> around = elements_around(mesh);
    for (Index n = 0; n < mesh.node_count(); ++n) {
        if (!mesh.has_exact_normal(n) && is_fold(around[at(n)], normals, cos_fold)) {
            folds.push_back(n);
        }
    }
    return folds;
}

ElementDirectors element_directors(const ShellMesh& mesh) {
    const std::vector<Vec3> nodal = mesh.nodal_normals();
    ElementDirectors directors(at(mesh.element_count()));
    for (Index e = 0; e < mesh.element_count(); ++e) {
        for (std::size_t k = 0; k < 4; ++k) {
            directors[at(e)][k] = nodal[at(mesh.element(e).nodes[k])];
        }
    }
    const std::vector<Index> folds = fold_nodes(mesh);
    if (folds.empty()) {
        return directors;
    }
    const double cos_fold = std::cos(mesh.fold_angle());
    const std::vector<Vec3> normals = element_normals(mesh);
    const std::vector<std::vector<Index>> around = elements_around(mesh);
    for (const Index n : folds) {
        for (const Index e : around[at(n)]) {
            const Vec3 director = fold_director(e, around[at(n)], normals, cos_fold);
            for (std::size_t k = 0; k < 4; ++k) {
                if (mesh.element(e).nodes[k] == n) {
                    directors[at(e)][k] = director;
                }
            }
        }
    }
    return directors;
}

} // namespace grainload::fem
