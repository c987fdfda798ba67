// Quarter of the body of a four-axle hopper wagon for sand and gravel (Faccns/Falns type):
// x along the wagon from its middle (x = 0), y across from its centre line (y = 0), z up from
// the top of rail; the planes x = 0 and y = 0 are symmetry planes. Every dimension and its
// source: cases/hopper_wagon/README.md. Lengths in m.
//
// One hopper section per half wagon: a longitudinal saddle (ridge over the centre sill, slope
// sheets falling at 49 deg to the side doors), an end slope sheet and a middle slope sheet
// (the transverse ridge between the two sections) at the same angle, vertical side and end
// walls, a top-hinged side door between the two slope sheets, and the body bolster that
// carries the body to the bogie pivot. All surfaces are plane; normals point into the load.

SetFactory("Built-in");

DefineConstant[ h = {0.2, Name "mesh size before subdivision [m]"} ];

a = 6.33;      // half body length (loading opening 12 660 mm, Greenbrier Falns 87 m3)
b = 1.50;      // half body width (3 000 mm, within the 3 090 mm maximum of the Cemet Fals 24 Ve)
z_top = 3.50;  // top of the side and end walls (3 575 mm maximum height, Cemet Fals 24 Ve)
alpha = 49 * Pi / 180; // slope sheet angle (Greenbrier Falns 87 m3)
z_sill = 0.90; // door sill: lower edge of the slope sheets at the side (assumed)
x_mid = 0.35;  // the middle slope sheet reaches the side at x = x_mid (assumed)
x_end = x_mid + 5.43; // door length 5 430 mm (Greenbrier Falns: unloading length 4 x 5 430 mm)
z_hinge = z_sill + 0.70; // door height 700 mm (assumed); the hinge is its top edge
x_pivot = 3.75; // bogie pivot: pivot pitch 7 500 mm (UIC 571-3 saddle-bottomed wagon Fals)
z_pivot = 1.00; // underside of the body bolster on the bogie centre plate (assumed)
y_plate = 0.15; // centre plate radius (assumed)
y_bolster = 1.00; // the bolster web runs from the centre line to y = 1 m (assumed)
y_ridge = 0.20;   // half width of the ridge over the centre sill (assumed)
w_chord = 0.20;   // top chord: a flange 200 mm wide round the top of the side and end walls (assumed)
d_tie = 0.20;     // transverse ties: strips 200 mm deep under the top, across the body (assumed)
x_ties[] = {1.25, 2.50, 3.75, 5.00}; // tie positions along the body (assumed, about 1.25 m apart)

t = Tan(alpha);
z_ridge = z_sill + b * t;              // saddle: z = z_ridge - y tan(alpha)
z_end = z_sill + (a - x_end) * t;      // end slope sheet at the end wall
z_middle = z_sill + x_mid * t;         // middle slope sheet at x = 0
y_end_hip = b - (a - x_end);           // hip of saddle and end slope at the end wall
y_middle_hip = b - x_mid;              // hip of saddle and middle slope at x = 0

Point(1) = {0, 0, z_ridge, h};
Point(2) = {x_pivot, 0, z_ridge, h};
Point(3) = {a, 0, z_ridge, h};
Point(4) = {0, y_ridge, z_ridge - y_ridge * t, h};
Point(5) = {x_pivot, y_ridge, z_ridge - y_ridge * t, h};
Point(6) = {a, y_ridge, z_ridge - y_ridge * t, h};
Point(7) = {0, y_middle_hip, z_middle, h};
Point(8) = {x_mid, b, z_sill, h};
Point(9) = {x_pivot, b, z_sill, h};
Point(10) = {x_end, b, z_sill, h};
Point(11) = {a, y_end_hip, z_end, h};
Point(12) = {x_pivot, y_bolster, z_ridge - y_bolster * t, h};
Point(13) = {0, b, z_middle, h};
Point(14) = {a, b, z_end, h};
Point(15) = {x_mid, b, z_hinge, h};
Point(16) = {x_end, b, z_hinge, h};
Point(17) = {0, b, z_top, h};
Point(18) = {a, b, z_top, h};
Point(19) = {a, 0, z_top, h};
Point(20) = {x_pivot, 0, z_pivot, h};
Point(21) = {x_pivot, y_plate, z_pivot, h};
Point(22) = {x_pivot, y_bolster, z_pivot, h};

Line(1) = {1, 2};   Line(2) = {2, 3};   Line(3) = {3, 6};   Line(4) = {6, 5};
Line(5) = {5, 4};   Line(6) = {4, 1};   Line(7) = {2, 5};   Line(8) = {4, 7};
Line(9) = {7, 8};   Line(10) = {8, 9};  Line(11) = {9, 12}; Line(12) = {12, 5};
Line(13) = {9, 10}; Line(14) = {10, 11}; Line(15) = {11, 6}; Line(16) = {7, 13};
Line(17) = {13, 8}; Line(18) = {11, 14}; Line(19) = {14, 10}; Line(20) = {8, 15};
Line(21) = {15, 16}; Line(22) = {16, 10}; Line(23) = {13, 17};
Line(25) = {18, 14}; Line(26) = {19, 3}; Line(27) = {18, 19}; Line(28) = {20, 21};
Line(29) = {21, 22}; Line(30) = {22, 12}; Line(31) = {20, 2};

// Loops run counter-clockwise seen from inside the hopper, so every normal points into it.
Curve Loop(1) = {1, 7, 5, 6};                  Plane Surface(1) = {1};  // ridge, x < x_pivot
Curve Loop(2) = {2, 3, 4, -7};                 Plane Surface(2) = {2};  // ridge, x > x_pivot
Curve Loop(3) = {-5, -12, -11, -10, -9, -8};   Plane Surface(3) = {3};  // slope sheet
Curve Loop(4) = {-4, -15, -14, -13, 11, 12};   Plane Surface(4) = {4};  // slope sheet
Curve Loop(5) = {9, -17, -16};                 Plane Surface(5) = {5};  // middle slope sheet
Curve Loop(6) = {14, 18, 19};                  Plane Surface(6) = {6};  // end slope sheet
Curve Loop(7) = {10, 13, -22, -21, -20};       Plane Surface(7) = {7};  // door
// The side wall's top edge runs through the ties' top corners (points 40 + k below).
Point(40) = {x_ties[0], b, z_top, h}; Point(41) = {x_ties[1], b, z_top, h};
Point(42) = {x_ties[2], b, z_top, h}; Point(43) = {x_ties[3], b, z_top, h};
Line(40) = {17, 40}; Line(41) = {40, 41}; Line(42) = {41, 42}; Line(43) = {42, 43};
Line(44) = {43, 18};
Curve Loop(8) = {17, 20, 21, 22, -19, -25, -44, -43, -42, -41, -40, -23};
Plane Surface(8) = {8}; // side wall
Curve Loop(9) = {-26, -27, 25, -18, 15, -3};   Plane Surface(9) = {9};  // end wall
Curve Loop(10) = {31, 7, -12, -30, -29, -28};  Plane Surface(10) = {10}; // body bolster

// Top chord: a horizontal flange round the top of the side wall and the end wall, outside
// the load (z = z_top), cut by the symmetry planes at x = 0 and y = 0.
Point(50) = {a + w_chord, 0, z_top, h};
Point(51) = {a + w_chord, b + w_chord, z_top, h};
Point(52) = {0, b + w_chord, z_top, h};
Line(50) = {19, 50}; Line(51) = {50, 51}; Line(52) = {51, 52}; Line(53) = {52, 17};
Curve Loop(11) = {40, 41, 42, 43, 44, 27, 50, 51, 52, 53}; Plane Surface(11) = {11}; // chord

// Transverse ties: vertical strips in the planes x = x_ties[k] from the centre line to the
// side wall, under the top (above the load), welded to the side wall along a short vertical
// line; by symmetry each is half a tie joining the two side walls.
For k In {0 : 3}
  Point(60 + 4 * k) = {x_ties[k], 0, z_top, h};
  Point(61 + 4 * k) = {x_ties[k], 0, z_top - d_tie, h};
  Point(62 + 4 * k) = {x_ties[k], b, z_top - d_tie, h};
  Line(60 + 4 * k) = {60 + 4 * k, 61 + 4 * k};
  Line(61 + 4 * k) = {61 + 4 * k, 62 + 4 * k};
  Line(62 + 4 * k) = {62 + 4 * k, 40 + k};
  Line(63 + 4 * k) = {40 + k, 60 + 4 * k};
  Curve Loop(20 + k) = {60 + 4 * k, 61 + 4 * k, 62 + 4 * k, 63 + 4 * k};
  Plane Surface(20 + k) = {20 + k};
  Curve{62 + 4 * k} In Surface{8}; // the weld line: the side wall's mesh follows it
EndFor

Physical Surface("ridge") = {1, 2};
Physical Surface("slope_sheet") = {3, 4};
Physical Surface("middle_slope_sheet") = {5};
Physical Surface("end_slope_sheet") = {6};
Physical Surface("door") = {7};
Physical Surface("side_wall") = {8};
Physical Surface("end_wall") = {9};
Physical Surface("bolster") = {10};
Physical Surface("top_chord") = {11};
Physical Surface("tie") = {20, 21, 22, 23};

Physical Curve("symmetry_x0") = {6, 8, 16, 23, 53};
Physical Curve("symmetry_y0") = {1, 2, 26, 31, 50, 60, 64, 68, 72};
Physical Curve("door_hinge") = {21};
Physical Curve("door_sill") = {10, 13};
Physical Curve("bogie_pivot") = {28};

// First-order quadrangles: the plane surfaces are meshed with triangles (Frontal-Delaunay;
// Gmsh 4.8.4 of Debian 12 crashes in its quad-oriented algorithm 8 on this geometry),
// recombined into quadrangles (Blossom), and every element is split once more so that none is
// left a triangle (Gmsh manual, Mesh.SubdivisionAlgorithm = 1): the final size is about h / 2,
// 6278 quadrangles and 6467 nodes at h = 0.2 m.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;
Mesh.MeshSizeMax = h;
