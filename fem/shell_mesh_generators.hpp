#pragma once
// Structured shell meshes with named edge sets: plate, cylinder, sphere zone, cone, box.

#include "fem/shell_mesh.hpp"

namespace grainload::fem {

/// Structured mesh generators. Each names its boundary edges as node sets (listed per
/// generator) and puts every node in "all" and every element in "all".

/// Flat rectangle [0, lx] x [0, ly] in the xy-plane; sets x0, x1, y0, y1.
ShellMesh make_plate(double lx, double ly, int nx, int ny, double thickness);

/// Cylinder segment of the given radius about the y-axis: x = R sin(phi), z = R cos(phi),
/// phi in [phi0, phi1] (from +z towards +x), y in [0, length]; sets phi0, phi1, y0, y1.
ShellMesh make_cylinder(double radius, double length, double phi0, double phi1, int n_phi, int n_y,
                        double thickness);

/// Spherical zone about the z-axis: polar angle in [polar0, polar1], azimuth in
/// [0, azimuth1]; sets polar0 (e.g. the hole), polar1 (e.g. the equator), azimuth0, azimuth1.
ShellMesh make_sphere_zone(double radius, double polar0, double polar1, double azimuth1,
                           int n_polar, int n_azimuth, double thickness);

/// Cone (hopper) about the z-axis from radius r0 at z = 0 to r1 at z = height, azimuth in
/// [0, azimuth1]; sets z0, z1, azimuth0, azimuth1.
ShellMesh make_cone(double r0, double r1, double height, double azimuth1, int n_azimuth,
                    int n_height, double thickness);

/// Rectangular box [0, lx] x [0, ly] x [0, lz] of quads (a silo or wagon body): the bottom,
/// the four walls and, when `closed_top`, the top, with shared nodes along the edges and
/// outward normals (a positive pressure pushes outward). Its edges are 90 deg fold lines
/// (fem/shell_directors.hpp). Node sets: bottom (z = 0, its edge included), bottom_edge (the
/// z = 0 perimeter), top (z = lz), top_edge (the z = lz perimeter, the rim of an open box),
/// x0, x1, y0, y1 (each wall with its edges), all; element sets bottom, top, x0, x1, y0, y1,
/// all.
ShellMesh make_box(double lx, double ly, double lz, int nx, int ny, int nz, bool closed_top,
                   double thickness);

} // namespace grainload::fem
