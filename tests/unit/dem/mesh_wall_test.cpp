// The DEM's mesh walls: the nearest point of a triangle, the face grid, and one touch per place
// where triangles share an edge or a plane, two at a concave fold.

#include "dem/plane_wall.hpp"

#include <gtest/gtest.h>
#include <random>

namespace {

using namespace grainload;
using dem::PlaneWall;

/// The point of the triangle a + s e1 + t e2 nearest `p`, by brute force over a fine lattice
/// of (s, t), for comparison: its error is below the lattice's pitch times the edges' length.
Vec3 nearest_by_lattice(const Vec3& a, const Vec3& e1, const Vec3& e2, const Vec3& p, int n) {
    Vec3 best = a;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; i + j <= n; ++j) {
            const Vec3 q = a + (double(i) / n) * e1 + (double(j) / n) * e2;
            if ((q - p).squaredNorm() < (best - p).squaredNorm()) {
                best = q;
            }
        }
    }
    return best;
}

// 2000 random points about a random triangle: the region tests give the distance the lattice
// of 400 steps per edge gives, within its pitch (edges < 2 m: 2 m / 400 = 5 mm, and a distance
// is off by at most the pitch's square over the distance beyond it; 5 mm bounds both).
TEST(MeshWall, NearestPointOfATriangleIsTheLatticesNearest) {
    std::mt19937_64 generator(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Vec3 a(0.1, -0.2, 0.3);
    const Vec3 e1(1.2, 0.3, -0.1);
    const Vec3 e2(0.2, 0.9, 0.4);
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p = a + Vec3(2 * unit(generator), 2 * unit(generator), 2 * unit(generator));
        const Vec3 mine = a + dem::nearest_on_triangle(p - a, e1, e2);
        const Vec3 lattice = nearest_by_lattice(a, e1, e2, p, 400);
        // Never farther than the lattice's best (it is the exact nearest), and nearer by less
        // than the lattice's pitch allows.
        worst = std::max(worst, (lattice - p).norm() - (mine - p).norm());
        EXPECT_LE((mine - p).norm(), (lattice - p).norm() + 1e-12);
        EXPECT_NEAR((mine - p).norm(), (lattice - p).norm(), 5e-3);
    }
    std::cout << "largest shortfall below the lattice's distance " << worst << " m\n";
}

/// The square [0, 1]^2 in z = 0 as n x n quads, each split in two.
io::SurfaceMesh square_mesh(int n) {
    io::SurfaceMesh mesh;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            mesh.vertices.emplace_back(double(i) / n, double(j) / n, 0.0);
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Index v = j * (n + 1) + i;
            mesh.quads.push_back({v, v + 1, v + n + 2, v + n + 1});
        }
    }
    return mesh;
}

// A sphere of radius 0.05 at 0.04 above a tessellated square touches it once wherever its centre
// lies: over a triangle, over an edge two share, over a corner eight share; with the plane's
// overlap 0.01 and normal +z.
TEST(MeshWall, ATessellatedPlaneIsTouchedOnceAnywhere) {
    PlaneWall wall;
    wall.set_mesh(square_mesh(10));
    wall.index_faces(0.06);
    std::vector<PlaneWall::Touch> touched;
    for (const Vec3& centre : {Vec3(0.33, 0.47, 0.04), Vec3(0.3, 0.47, 0.04), Vec3(0.3, 0.4, 0.04),
                               Vec3(0.35, 0.35, 0.04)}) {
        wall.touching_faces(centre, 0.05, touched);
        ASSERT_EQ(touched.size(), 1u) << centre.transpose();
        EXPECT_NEAR(touched[0].overlap, 0.01, 1e-15);
        EXPECT_NEAR(touched[0].normal.z(), 1.0, 1e-15);
    }
    // Beyond the square's edge, only its rim: one touch, at the edge.
    wall.touching_faces(Vec3(1.03, 0.5, 0.0), 0.05, touched);
    ASSERT_EQ(touched.size(), 1u);
    EXPECT_NEAR(touched[0].overlap, 0.02, 1e-15);
    EXPECT_NEAR(touched[0].normal.x(), 1.0, 1e-15);
    // Out of reach: no touch, and the grid lists no face far off the mesh.
    wall.touching_faces(Vec3(0.5, 0.5, 0.06), 0.05, touched);
    EXPECT_TRUE(touched.empty());
    EXPECT_TRUE(wall.grid.near(Vec3(0.5, 0.5, 0.5)).empty());
}

// A mesh wall that follows moving vertices (a coupled shell's mid-surface) is a plate of its
// thickness: a sphere of radius 0.05 touches the square z = 0 of half-thickness 0.004 from 0.054
// above or below it, not from 0.055 (a source's grains are placed clear of it); as its
// vertices move up by 0.01 over [0, 1] s the faces follow, halfway at 0.5 s, and a point of a
// face moves at 0.01 m/s.
TEST(MeshWall, AFollowingWallIsAPlateOfItsThicknessOnItsMovingVertices) {
    PlaneWall wall;
    const io::SurfaceMesh mesh = square_mesh(2);
    wall.set_mesh(mesh);
    wall.half_thickness = 0.004;
    wall.set_interval(mesh.vertices, 0.0, 0.0);
    EXPECT_TRUE(wall.touched_by(Vec3(0.3, 0.6, 0.0539), 0.05));
    EXPECT_TRUE(wall.touched_by(Vec3(0.3, 0.6, -0.0539), 0.05));
    EXPECT_FALSE(wall.touched_by(Vec3(0.3, 0.6, 0.055), 0.05));
    std::vector<Vec3> raised = mesh.vertices;
    for (Vec3& v : raised) {
        v.z() += 0.01;
    }
    wall.set_interval(raised, 0.0, 1.0);
    wall.follow(0.5);
    for (const PlaneWall::Face& face : wall.faces) {
        EXPECT_NEAR(face.point.z(), 0.005, 1e-15);
        EXPECT_NEAR((face.point + face.edge_u).z(), 0.005, 1e-15);
    }
    const Vec3 point(0.3, 0.6, 0.005);
    EXPECT_NEAR((wall.face_velocity(0, point) - Vec3(0.0, 0.0, 0.01)).norm(), 0.0, 1e-15);
    const Vec3 weights = wall.barycentric(0, wall.faces[0].point + 0.25 * wall.faces[0].edge_u +
                                                 0.5 * wall.faces[0].edge_v);
    EXPECT_NEAR((weights - Vec3(0.25, 0.25, 0.5)).norm(), 0.0, 1e-15);
}

// A floor and a wall meeting at a right angle (a concave fold), both tessellated: a sphere in
// the corner touches each once, with each one's overlap; over the ridge of a roof (a convex
// fold) it touches once, at the ridge.
TEST(MeshWall, AConcaveFoldIsTouchedOnEachSideAConvexOneOnce) {
    io::SurfaceMesh fold;
    fold.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 1}, {1, 1, 1}};
    fold.quads = {{0, 1, 2, 3}, {1, 4, 5, 2}};
    PlaneWall corner;
    corner.set_mesh(fold);
    corner.index_faces(0.06);
    std::vector<PlaneWall::Touch> touched;
    corner.touching_faces(Vec3(0.96, 0.5, 0.03), 0.05, touched);
    ASSERT_EQ(touched.size(), 2u);
    EXPECT_NEAR(touched[0].overlap + touched[1].overlap, 0.02 + 0.01, 1e-15);

    io::SurfaceMesh roof;
    roof.vertices = {{0, 0, 0}, {1, 0, 0.5}, {1, 1, 0.5}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    roof.quads = {{0, 1, 2, 3}, {1, 4, 5, 2}};
    PlaneWall ridge;
    ridge.set_mesh(roof);
    ridge.index_faces(0.06);
    ridge.touching_faces(Vec3(1.0, 0.5, 0.54), 0.05, touched);
    ASSERT_EQ(touched.size(), 1u);
    EXPECT_NEAR(touched[0].overlap, 0.01, 1e-15);
    EXPECT_NEAR(touched[0].normal.z(), 1.0, 1e-15);
}

// Neighbours across edges: a quad's two triangles share its diagonal; the fold's quads share
// the edge at x = 1; the outer edges have none.
TEST(MeshWall, TrianglesKnowTheirNeighboursAcrossSharedEdges) {
    PlaneWall wall;
    wall.set_mesh(square_mesh(1));
    ASSERT_EQ(wall.faces.size(), 2u);
    int shared = 0;
    for (const auto& sides : wall.adjacent) {
        for (const std::int32_t other : sides) {
            shared += other >= 0;
        }
    }
    EXPECT_EQ(shared, 2);
    EXPECT_NE(std::find(wall.adjacent[0].begin(), wall.adjacent[0].end(), 1),
              wall.adjacent[0].end());
}

} // namespace
