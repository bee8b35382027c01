// Dissertation 6.5 (Figs. 25-28): a wedge pushed into a notch. Two prisms
// extruded in z by `thick`:
//   the notched block (material id 1): the square [0,1] x [0,1] with a
//     V-notch cut into its right side, apex at (1 - depth, 0.5);
//   the wedge (material id 2): [1 + gap, 2] x [0, 1] plus a triangular tip
//     of the notch's shape, pointing left, apex at (1 - depth + gap, 0.5).
// Boundary ids: 1 the block's left face (clamped), 2 the wedge's right face
// (pushed), 3 the two notch faces (contact surface), 4 the two faces of
// the wedge's tip (contact surface), 5 all other faces.
//   gmsh -3 -format msh2 -setnumber lc 0.1 wedge_in_notch.geo -o wedge_in_notch.msh
DefineConstant[ lc = 0.1, depth = 0.4, gap = 0.05, thick = 0.2 ];

Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1 - depth, 0.5, 0, lc};
Point(4) = {1, 1, 0, lc};
Point(5) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Point(11) = {1 + gap, 0, 0, lc};
Point(12) = {2, 0, 0, lc};
Point(13) = {2, 1, 0, lc};
Point(14) = {1 + gap, 1, 0, lc};
Point(15) = {1 - depth + gap, 0.5, 0, lc};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

block[] = Extrude {0, 0, thick} { Surface{1};};
wedge[] = Extrude {0, 0, thick} { Surface{2};};
// Extrude returns: [0] top, [1] volume, [2..] the lateral faces in the
// order of the curve loop
Physical Volume(1) = {block[1]};
Physical Volume(2) = {wedge[1]};
Physical Surface(1) = {block[6]};
Physical Surface(3) = {block[3], block[4]};
Physical Surface(2) = {wedge[3]};
Physical Surface(4) = {wedge[5], wedge[6]};
Physical Surface(5) = {1, block[0], block[2], block[5],
                       2, wedge[0], wedge[2], wedge[4]};
