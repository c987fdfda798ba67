// Quarter of the body of a four-axle hopper wagon for sand and gravel (Faccns/Falns type):
// x along the wagon from its middle (x = 0), y across from its centre line (y = 0), z up from
// the top of rail; the planes x = 0 and y = 0 are symmetry planes. Every dimension and its
// source: cases/hopper_wagon/README.md. Lengths in m.
//
// One hopper section per half wagon: a longitudinal saddle (ridge over the centre sill, slope
// sheets falling at 49 deg to the side doors), an end slope sheet and a middle slope sheet
// (the transverse ridge between the two sections) at the same angle, vertical side and end
// walls, a top-hinged side door between the two slope sheets, and the body bolster that
// carries the body to the bogie pivot. Outside the load: a top chord, a box hinge beam along
// the door's top edge, and ten frames (a rib under the saddle and slope sheet, a stanchion on
// the side wall; five carry a transverse tie under the top). All surfaces are plane; the
// sheets' normals point into the load.

SetFactory("Built-in");

DefineConstant[ h = {0.2, Name "mesh size before subdivision [m]"} ];
// The door opening's height: 700 mm (assumed); a case may draw it taller (geo_numbers) to
// make up for the contact potential's reach at the opening's edges (docs/validation/silo.md).
DefineConstant[ door = {0.70, Name "door opening height [m]"} ];

a = 6.33;      // half body length (loading opening 12 660 mm, Greenbrier Falns 87 m3)
b = 1.50;      // half body width (3 000 mm, within the 3 090 mm maximum of the Cemet Fals 24 Ve)
z_top = 3.50;  // top of the side and end walls (3 575 mm maximum height, Cemet Fals 24 Ve)
alpha = 49 * Pi / 180; // slope sheet angle (Greenbrier Falns 87 m3)
z_sill = 0.90; // door sill: lower edge of the slope sheets at the side (assumed)
x_mid = 0.35;  // the middle slope sheet reaches the side at x = x_mid (assumed)
x_end = x_mid + 5.43; // door length 5 430 mm (Greenbrier Falns: unloading length 4 x 5 430 mm)
z_hinge = z_sill + door; // door height 700 mm (assumed); the hinge is its top edge
x_pivot = 3.75; // bogie pivot: pivot pitch 7 500 mm (UIC 571-3 saddle-bottomed wagon Fals)
z_pivot = 1.00; // underside of the body bolster on the bogie centre plate (assumed)
y_plate = 0.15; // centre plate radius (assumed)
y_bolster = 1.00; // the bolster web runs from the centre line to y = 1 m (assumed)
y_ridge = 0.20;   // half width of the ridge over the centre sill (assumed)
w_chord = 0.20;   // top chord: a flange 200 mm wide round the top of the side and end walls (assumed)
d_tie = 0.20;     // transverse ties: strips 200 mm deep under the top, across the body (assumed)
// Frames (assumed): ten, at x = x_mid + k p (k = 0..9, p = 603 mm), from door post to door post;
// each has a rib under the saddle and slope sheet and a stanchion outside the side wall, the
// odd ones a tie (five ties, 1.21 m apart).
p_frame = (x_end - x_mid) / 9;
d_rib = 0.15;       // ribs: 150 mm deep normal to the slope sheets (assumed)
w_stanchion = 0.15; // stanchions and door posts: 150 mm out from the side wall (assumed)
w_hinge = 0.30;     // hinge beam: a closed box 300 x 300 mm along the door's top edge (assumed)

t = Tan(alpha);
z_ridge = z_sill + b * t;              // saddle: z = z_ridge - y tan(alpha)
z_end = z_sill + (a - x_end) * t;      // end slope sheet at the end wall
z_middle = z_sill + x_mid * t;         // middle slope sheet at x = 0
y_end_hip = b - (a - x_end);           // hip of saddle and end slope at the end wall
y_middle_hip = b - x_mid;              // hip of saddle and middle slope at x = 0

e_rib = d_rib / Cos(alpha);            // the ribs' vertical depth

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

// The frames' points: on the saddle's centre line (100 + k) and ridge edge (110 + k), on the
// sill (120 + k; the door posts' are points 8 and 10), on the side wall along the hinge
// beam's top (130 + k) and at its top (140 + k). The lines along the body are chains through
// them (and through the bogie pivot's points 2, 5, 9), so every stiffener's weld line ends on
// mesh vertices: CP/LC the centre line, EP/LE the ridge edge, SP/LS the sill, GP/LG the hinge
// beam's top on the side wall, TP/LT the wall top.
For k In {0 : 9}
  xk = x_mid + k * p_frame;
  Point(100 + k) = {xk, 0, z_ridge, h};
  Point(110 + k) = {xk, y_ridge, z_ridge - y_ridge * t, h};
  If (k > 0 && k < 9)
    Point(120 + k) = {xk, b, z_sill, h};
  EndIf
  Point(130 + k) = {xk, b, z_hinge + w_hinge, h};
  Point(140 + k) = {xk, b, z_top, h};
EndFor
Point(150) = {0, b, z_hinge, h};           // the hinge beam's bottom at x = 0 ...
Point(151) = {a, b, z_hinge, h};           // ... and at the end wall
Point(154) = {0, b, z_hinge + w_hinge, h}; // its top at x = 0 ...
Point(155) = {a, b, z_hinge + w_hinge, h}; // ... and at the end wall
CP[] = {1}; EP[] = {4}; SP[] = {8}; GP[] = {154}; TP[] = {17};
For k In {0 : 9}
  If (k == 6)
    CP[] += {2}; EP[] += {5}; SP[] += {9};
  EndIf
  CP[] += {100 + k}; EP[] += {110 + k}; GP[] += {130 + k}; TP[] += {140 + k};
  If (k > 0 && k < 9)
    SP[] += {120 + k};
  EndIf
EndFor
CP[] += {3}; EP[] += {6}; SP[] += {10}; GP[] += {155}; TP[] += {18};
LC[] = {}; LE[] = {}; LS[] = {}; LG[] = {}; LT[] = {};
For i In {0 : 11}
  LC[] += {200 + i}; Line(200 + i) = {CP[i], CP[i + 1]};
  LE[] += {215 + i}; Line(215 + i) = {EP[i], EP[i + 1]};
EndFor
For i In {0 : 9}
  LS[] += {230 + i}; Line(230 + i) = {SP[i], SP[i + 1]};
EndFor
For i In {0 : 10}
  LG[] += {240 + i}; Line(240 + i) = {GP[i], GP[i + 1]};
  LT[] += {400 + i}; Line(400 + i) = {TP[i], TP[i + 1]};
EndFor

Line(3) = {3, 6};   Line(6) = {4, 1};   Line(7) = {2, 5};   Line(8) = {4, 7};
Line(9) = {7, 8};   Line(11) = {9, 12}; Line(12) = {12, 5};
Line(14) = {10, 11}; Line(15) = {11, 6}; Line(16) = {7, 13};
Line(17) = {13, 8}; Line(18) = {11, 14}; Line(19) = {14, 10}; Line(20) = {8, 15};
Line(21) = {15, 16}; Line(22) = {16, 10}; Line(23) = {13, 150}; Line(24) = {150, 154};
Line(40) = {154, 17}; Line(25) = {18, 155}; Line(39) = {155, 151}; Line(32) = {151, 14};
Line(26) = {19, 3}; Line(27) = {18, 19}; Line(28) = {20, 21};
Line(29) = {21, 22}; Line(30) = {22, 12}; Line(31) = {20, 2};
Line(34) = {150, 15}; Line(35) = {16, 151};

// Loops run counter-clockwise seen from inside the hopper, so every normal points into it.
// The saddle's chains have the pivot's points at index 7, the sill's at index 6.
Curve Loop(1) = {LC[{0 : 6}], 7, -LE[{6 : 0 : -1}], 6};
Plane Surface(1) = {1}; // ridge, x < x_pivot
Curve Loop(2) = {LC[{7 : 11}], 3, -LE[{11 : 7 : -1}], -7};
Plane Surface(2) = {2}; // ridge, x > x_pivot
Curve Loop(3) = {LE[{0 : 6}], -12, -11, -LS[{5 : 0 : -1}], -9, -8};
Plane Surface(3) = {3}; // slope sheet
Curve Loop(4) = {LE[{7 : 11}], -15, -14, -LS[{9 : 6 : -1}], 11, 12};
Plane Surface(4) = {4}; // slope sheet
Curve Loop(5) = {9, -17, -16};                 Plane Surface(5) = {5};  // middle slope sheet
Curve Loop(6) = {14, 18, 19};                  Plane Surface(6) = {6};  // end slope sheet
Curve Loop(7) = {LS[], -22, -21, -20};         Plane Surface(7) = {7};  // door
// The side wall in four plane pieces (Blossom's recombination failed on it as one surface
// with the hinge beam's weld lines embedded at some h): above the hinge beam; the hinge beam's
// inner web (z_hinge .. z_hinge + w_hinge; the flanges' weld lines 34, 21, 35 and LG are its
// edges); beside the door at the middle and at the end, below the hinge beam.
Curve Loop(8) = {LG[], -25, -LT[{10 : 0 : -1}], -40};  Plane Surface(8) = {8};
Curve Loop(12) = {34, 21, 35, -39, -LG[{10 : 0 : -1}], -24}; Plane Surface(12) = {12};
Curve Loop(13) = {17, 20, -34, -23};                  Plane Surface(13) = {13};
Curve Loop(14) = {22, -19, -32, -35};                 Plane Surface(14) = {14};
Curve Loop(9) = {-26, -27, 25, 39, 32, -18, 15, -3}; Plane Surface(9) = {9};  // end wall
Curve Loop(10) = {31, 7, -12, -30, -29, -28};  Plane Surface(10) = {10}; // body bolster

// Top chord: a horizontal flange round the top of the side wall and the end wall, outside
// the load (z = z_top), cut by the symmetry planes at x = 0 and y = 0.
Point(50) = {a + w_chord, 0, z_top, h};
Point(51) = {a + w_chord, b + w_chord, z_top, h};
Point(52) = {0, b + w_chord, z_top, h};
Line(50) = {19, 50}; Line(51) = {50, 51}; Line(52) = {51, 52}; Line(53) = {52, 17};
Curve Loop(11) = {LT[], 27, 50, 51, 52, 53}; Plane Surface(11) = {11}; // chord

// Transverse ties at the odd frames: vertical strips from the centre line to the side wall,
// under the top (above the load), welded to the side wall along a short vertical line; by
// symmetry each is half a tie joining the two side walls.
For j In {0 : 4}
  xj = x_mid + (2 * j + 1) * p_frame;
  Point(60 + 4 * j) = {xj, 0, z_top, h};
  Point(61 + 4 * j) = {xj, 0, z_top - d_tie, h};
  Point(62 + 4 * j) = {xj, b, z_top - d_tie, h};
  Line(60 + 4 * j) = {60 + 4 * j, 61 + 4 * j};
  Line(61 + 4 * j) = {61 + 4 * j, 62 + 4 * j};
  Line(62 + 4 * j) = {62 + 4 * j, 141 + 2 * j};
  Line(63 + 4 * j) = {141 + 2 * j, 60 + 4 * j};
  Curve Loop(20 + j) = {60 + 4 * j, 61 + 4 * j, 62 + 4 * j, 63 + 4 * j};
  Plane Surface(20 + j) = {20 + j};
  Curve{62 + 4 * j} In Surface{8}; // the weld line: the side wall's mesh follows it
EndFor

// Hinge beam (side sill): a closed box w_hinge x w_hinge outside the side wall, over the whole
// length 0..a, its bottom flange along the door's top edge (z = z_hinge), an outer web, a top
// flange; the side wall's piece 12 is its inner web, the flanges' weld lines its edges.
Point(152) = {a, b + w_hinge, z_hinge, h};
Point(153) = {0, b + w_hinge, z_hinge, h};
Point(156) = {a, b + w_hinge, z_hinge + w_hinge, h};
Point(157) = {0, b + w_hinge, z_hinge + w_hinge, h};
Line(36) = {151, 152}; Line(37) = {152, 153}; Line(38) = {153, 150};
Line(41) = {152, 156}; Line(42) = {156, 157}; Line(43) = {157, 153};
Line(44) = {155, 156}; Line(45) = {157, 154};
Curve Loop(30) = {34, 21, 35, 36, 37, 38};    Plane Surface(30) = {30}; // bottom flange
Curve Loop(31) = {37, -43, -42, -41};         Plane Surface(31) = {31}; // outer web
Curve Loop(32) = {LG[], 44, 42, 45};          Plane Surface(32) = {32}; // top flange

// Stanchions: at each frame a strip w_stanchion wide in the plane of the frame outside the
// side wall, from the hinge beam's top to the top chord; its three welded edges are embedded
// in the side wall, the top flange and the chord. At the tie frames the weld line ends in the
// tie's. The door posts (frames 0 and 9, the door's ends) continue below the hinge beam down
// to their ribs' ends, beside the door's edge (lines 20, 22).
For k In {0 : 9}
  xk = x_mid + k * p_frame;
  Point(180 + k) = {xk, b + w_stanchion, z_hinge + w_hinge, h};
  Point(190 + k) = {xk, b + w_stanchion, z_top, h};
  Line(290 + k) = {180 + k, 130 + k};
  Line(300 + k) = {140 + k, 190 + k};
  Line(310 + k) = {190 + k, 180 + k};
  Curve{290 + k} In Surface{32};
  Curve{300 + k} In Surface{11};
  If (k % 2 == 0)
    Line(280 + k) = {130 + k, 140 + k};
    Curve Loop(100 + k) = {280 + k, 300 + k, 310 + k, 290 + k};
  Else
    Line(280 + k) = {130 + k, 62 + 2 * (k - 1)};
    Curve Loop(100 + k) = {280 + k, 62 + 2 * (k - 1), 300 + k, 310 + k, 290 + k};
  EndIf
  Curve{280 + k} In Surface{8};
  Plane Surface(100 + k) = {100 + k};
EndFor

// Ribs: at each frame a strip under the saddle and the slope sheet, d_rib deep normal to
// them, from the centre line (where the symmetry plane y = 0 holds it: a cross bearer through
// the centre sill) to the sill, its ends vertical; its weld line (ridge: 260 + k, slope sheet:
// 270 + k) is embedded in the sheets.
For k In {0 : 9}
  xk = x_mid + k * p_frame;
  i = (k < 6) ? k + 1 : k + 2; // the frame's index in CP and EP
  s = (k < 6) ? k : k + 1;     // ... and in SP
  Point(160 + k) = {xk, 0, z_ridge - e_rib, h};
  Point(170 + k) = {xk, b, z_sill - e_rib, h};
  Line(260 + k) = {CP[i], EP[i]};
  Line(270 + k) = {EP[i], SP[s]};
  Line(320 + k) = {SP[s], 170 + k};
  Line(330 + k) = {170 + k, 160 + k};
  Line(340 + k) = {160 + k, CP[i]};
  If (k < 6)
    Curve{260 + k} In Surface{1};
    Curve{270 + k} In Surface{3};
  Else
    Curve{260 + k} In Surface{2};
    Curve{270 + k} In Surface{4};
  EndIf
  Curve Loop(120 + k) = {260 + k, 270 + k, 320 + k, 330 + k, 340 + k};
  Plane Surface(120 + k) = {120 + k};
EndFor

// Door posts below the hinge beam: strips w_stanchion wide in the planes x = x_mid and
// x = x_end, from the rib's lower end (z_sill - e_rib) to the hinge beam's bottom flange, in
// which their top edge is embedded.
For j In {0 : 1}
  k = 9 * j;
  xk = x_mid + k * p_frame;
  Point(200 + j) = {xk, b + w_stanchion, z_sill - e_rib, h};
  Point(202 + j) = {xk, b + w_stanchion, z_hinge, h};
  Line(350 + j) = {170 + k, 200 + j};
  Line(352 + j) = {200 + j, 202 + j};
  Line(354 + j) = {202 + j, 15 + j};
  Curve{354 + j} In Surface{30};
EndFor
Curve Loop(110) = {20, -354, -352, -350, -320};   Plane Surface(110) = {110};
Curve Loop(111) = {-22, -355, -353, -351, -329};  Plane Surface(111) = {111};

Physical Surface("ridge") = {1, 2};
Physical Surface("slope_sheet") = {3, 4};
Physical Surface("middle_slope_sheet") = {5};
Physical Surface("end_slope_sheet") = {6};
Physical Surface("door") = {7};
Physical Surface("side_wall") = {8, 12, 13, 14};
Physical Surface("end_wall") = {9};
Physical Surface("bolster") = {10};
Physical Surface("top_chord") = {11};
Physical Surface("tie") = {20 : 24};
Physical Surface("hinge_beam") = {30, 31, 32};
Physical Surface("stanchion") = {100 : 111};
Physical Surface("rib") = {120 : 129};

Physical Curve("symmetry_x0") = {6, 8, 16, 23, 24, 40, 38, 43, 45, 53};
Physical Curve("symmetry_y0") = {LC[], 26, 31, 50, 60, 64, 68, 72, 76, 340 : 349};
Physical Curve("door_hinge") = {21};
Physical Curve("door_sill") = {LS[]};
Physical Curve("bogie_pivot") = {28};

// First-order quadrangles: the plane surfaces are meshed with triangles (Frontal-Delaunay;
// Gmsh 4.8.4 of Debian 12 crashes in its quad-oriented algorithm 8 on this geometry),
// recombined into quadrangles (Blossom), and every element is split once more so that none is
// left a triangle (Gmsh manual, Mesh.SubdivisionAlgorithm = 1): the final size is about h / 2,
// 9088 quadrangles and 9226 nodes at h = 0.2 m.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;
Mesh.MeshSizeMax = h;
