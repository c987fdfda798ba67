// One sloping sheet of the plane-wedge hopper (cases/hopper_discharge/hopper_shell*.toml) as a
// strip of shell between the planes y = 0 and y = depth: the right half of the hopper (x > 0),
// z up, the orifice's plane at z = 0. The sheet's mid-surface lies t/2 behind the rigid
// case's wall plane (from (0.2, 0) at 30 deg to the vertical, 1.8 m long), so that its face
// towards the sand, mid-surface + t/2, is that plane. Lengths in m. The surface's normal
// points towards the axis, into the sand.

SetFactory("Built-in");

DefineConstant[ h = {0.025, Name "mesh size [m]"} ];
DefineConstant[ depth = {0.15, Name "strip depth along y [m]"} ];
DefineConstant[ t = {0.008, Name "sheet thickness [m]"} ];
DefineConstant[ r0 = {0.2, Name "half-width of the orifice [m]"} ];
DefineConstant[ L = {1.8, Name "sheet length along the slope [m]"} ];
DefineConstant[ theta = {30, Name "sheet angle from the vertical [deg]"} ];

a = theta * Pi / 180;
// Outward normal (away from the sand): (cos a, 0, -sin a); the mid-surface is t/2 along it.
x0 = r0 + t / 2 * Cos(a);
z0 = -t / 2 * Sin(a);
x1 = x0 + L * Sin(a);
z1 = z0 + L * Cos(a);

Point(1) = {x0, 0, z0, h};
Point(2) = {x1, 0, z1, h};
Point(3) = {x1, depth, z1, h};
Point(4) = {x0, depth, z0, h};

Line(1) = {1, 2};        // y = 0: the symmetry plane's edge
Line(2) = {2, 3};        // the top edge
Line(3) = {3, 4};        // y = depth
Line(4) = {4, 1};        // the orifice's edge

// (first edge) x (next edge) = (slope) x (+y) points towards the axis.
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = Ceil(L / h) + 1;
Transfinite Curve{2, 4} = Ceil(depth / h) + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("sheet") = {1};
Physical Curve("orifice_edge") = {4};
Physical Curve("top_edge") = {2};
Physical Curve("y0") = {1};
Physical Curve("y1") = {3};

Mesh.MshFileVersion = 4.1;
