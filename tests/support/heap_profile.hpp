#pragma once
// A heap's height, run-out and kinetic energy measured from a frame.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace grainload::testing {

/// Sum of v^2 / 2 over the sand's particles: the kinetic energy per particle mass (all
/// particles have the same mass).
inline double kinetic_energy(vtkPolyData* sand) {
    vtkDataArray* velocity = sand->GetPointData()->GetArray("velocity");
    double sum = 0.0;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        const double* v = velocity->GetTuple3(i);
        sum += 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    return sum;
}

struct Heap {
    double height = 0.0;    ///< top particle centre above the bottom layer's, m
    double slope_deg = 0.0; ///< flank slope between 20 % and 80 % of the height
    double lowest = 0.0;    ///< lowest particle centre, m
    double farthest = 0.0;  ///< largest distance from the axis, m
    double outer_deg = 0.0; ///< atan(height / radius holding 99 % of the particles)
};

/// The heap's free surface: the highest particle centre in every ring of one spacing about
/// the tube's axis; the flank slope is the least-squares slope of those tops over the rings
/// outside the summit whose height lies between 20 % and 80 % of the heap's; the outer angle
/// is atan(H / R99), R99 the radius holding 99 % of the particles (as cases/repose/analyse.py).
inline Heap measure_heap(vtkPolyData* sand, double spacing) {
    std::map<int, double> top;
    std::vector<double> radii;
    Heap heap;
    heap.lowest = 1e9;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        double x[3];
        sand->GetPoint(i, x);
        heap.lowest = std::min(heap.lowest, x[2]);
        const double r = std::hypot(x[0], x[1]);
        heap.farthest = std::max(heap.farthest, r);
        radii.push_back(r);
        const int ring = static_cast<int>(r / spacing);
        top[ring] = top.contains(ring) ? std::max(top[ring], x[2]) : x[2];
    }
    int summit = top.begin()->first;
    for (auto& [ring, z] : top) {
        z -= heap.lowest;
        if (z > heap.height) {
            heap.height = z;
            summit = ring;
        }
    }
    double n = 0.0, sr = 0.0, sz = 0.0, srr = 0.0, srz = 0.0;
    for (const auto& [ring, z] : top) {
        if (ring > summit && z >= 0.2 * heap.height && z <= 0.8 * heap.height) {
            const double r = (ring + 0.5) * spacing;
            n += 1.0;
            sr += r;
            sz += z;
            srr += r * r;
            srz += r * z;
        }
    }
    const double slope = (n * srz - sr * sz) / (n * srr - sr * sr);
    heap.slope_deg = std::atan(-slope) * 180.0 / std::numbers::pi;
    const auto r99 =
        radii.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(radii.size() - 1));
    std::nth_element(radii.begin(), r99, radii.end());
    heap.outer_deg = std::atan(heap.height / *r99) * 180.0 / std::numbers::pi;
    return heap;
}

} // namespace grainload::testing
