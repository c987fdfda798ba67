// Both sloping sheets of the plane-wedge hopper (cases/hopper_discharge/hopper_shell_dem.toml)
// between the end plates y = 0 and y = depth: x across the orifice, z up, the orifice's plane at
// z = 0. Each sheet's mid-surface lies t/2 behind the rigid case's wall plane (from (+-r0, 0)
// at theta to the vertical, L long), so that a grain touching the sheet as a plate of
// thickness t meets that plane. Lengths in m. Both surfaces' normals point towards the axis,
// into the grains.

SetFactory("Built-in");

DefineConstant[ h = {0.05, Name "mesh size [m]"} ];
DefineConstant[ depth = {0.4, Name "depth along y [m]"} ];
DefineConstant[ t = {0.008, Name "sheet thickness [m]"} ];
DefineConstant[ r0 = {0.2, Name "half-width of the orifice [m]"} ];
DefineConstant[ L = {1.8, Name "sheet length along the slope [m]"} ];
DefineConstant[ theta = {30, Name "sheet angle from the vertical [deg]"} ];

a = theta * Pi / 180;
// The right sheet's outward normal (away from the grains): (cos a, 0, -sin a).
x0 = r0 + t / 2 * Cos(a);
z0 = -t / 2 * Sin(a);
x1 = x0 + L * Sin(a);
z1 = z0 + L * Cos(a);

// The right sheet (x > 0).
Point(1) = {x0, 0, z0, h};
Point(2) = {x1, 0, z1, h};
Point(3) = {x1, depth, z1, h};
Point(4) = {x0, depth, z0, h};
Line(1) = {1, 2};        // y = 0
Line(2) = {2, 3};        // the top edge
Line(3) = {3, 4};        // y = depth
Line(4) = {4, 1};        // the orifice's edge
// (first edge) x (next edge) = (slope) x (+y) points towards the axis.
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The left sheet, its mirror image in x = 0, its loop turned the other way so that its normal
// too points towards the axis.
Point(5) = {-x0, 0, z0, h};
Point(6) = {-x1, 0, z1, h};
Point(7) = {-x1, depth, z1, h};
Point(8) = {-x0, depth, z0, h};
Line(5) = {5, 8};        // the orifice's edge
Line(6) = {8, 7};        // y = depth
Line(7) = {7, 6};        // the top edge
Line(8) = {6, 5};        // y = 0
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};

Transfinite Curve{1, 3, 6, 8} = Ceil(L / h) + 1;
Transfinite Curve{2, 4, 5, 7} = Ceil(depth / h) + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("right") = {1};
Physical Surface("left") = {2};
Physical Curve("orifice_edges") = {4, 5};
Physical Curve("top_edges") = {2, 7};
Physical Curve("y0") = {1, 8};
Physical Curve("y1") = {3, 6};

Mesh.MshFileVersion = 4.1;
