// Quarter of a circular steel silo with a conical hopper: vertical axis z through
// the origin, the outlet's plane at z = 0; the planes x = 0 and y = 0 are symmetry planes.
// Lengths in m. The surfaces' normals point into the silo (towards the axis), where the sand
// is. Dimensions: cases/silo_hopper/README.md.

SetFactory("Built-in");

DefineConstant[ h = {0.025, Name "mesh size [m]"} ];
DefineConstant[ R = {0.15, Name "silo radius [m]"} ];
DefineConstant[ H = {0.9, Name "height of the cylinder [m]"} ];
DefineConstant[ r0 = {0.056, Name "outlet radius as drawn [m]"} ];
DefineConstant[ beta = {30, Name "hopper half-angle from the vertical [deg]"} ];

z_t = (R - r0) / Tan(beta * Pi / 180); // the transition: the cone meets the cylinder
z_top = z_t + H;

Point(1) = {0, 0, 0, h};
Point(2) = {0, 0, z_t, h};
Point(3) = {0, 0, z_top, h};
Point(4) = {r0, 0, 0, h};
Point(5) = {0, r0, 0, h};
Point(6) = {R, 0, z_t, h};
Point(7) = {0, R, z_t, h};
Point(8) = {R, 0, z_top, h};
Point(9) = {0, R, z_top, h};

Circle(1) = {4, 1, 5};   // the outlet's rim
Circle(2) = {6, 2, 7};   // the transition ring
Circle(3) = {8, 3, 9};   // the top rim
Line(4) = {4, 6};        // the hopper in the plane y = 0
Line(5) = {5, 7};        // the hopper in the plane x = 0
Line(6) = {6, 8};        // the cylinder in the plane y = 0
Line(7) = {7, 9};        // the cylinder in the plane x = 0

// Loops run so that (first edge) x (next edge) points towards the axis.
Curve Loop(1) = {4, 2, -5, -1};
Surface(1) = {1};        // the hopper
Curve Loop(2) = {6, 3, -7, -2};
Surface(2) = {2};        // the cylinder

// Structured quadrangles: the same divisions round every ring, so the hopper's and the
// cylinder's nodes meet on the transition ring.
n_round = Ceil(Pi * R / 2 / h) + 1;
Transfinite Curve{1, 2, 3} = n_round;
Transfinite Curve{4, 5} = Ceil(Sqrt((R - r0)^2 + z_t^2) / h) + 1;
Transfinite Curve{6, 7} = Ceil(H / h) + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("hopper") = {1};
Physical Surface("cylinder") = {2};
Physical Curve("symmetry_x0") = {5, 7};
Physical Curve("symmetry_y0") = {4, 6};
Physical Curve("outlet_rim") = {1};
Physical Curve("transition") = {2};
Physical Curve("top_rim") = {3};

Mesh.MshFileVersion = 4.1;
