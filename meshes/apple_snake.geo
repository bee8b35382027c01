// The snake swallowing an apple (dissertation 8.1, Fig. 50): a tube along
// x whose mouth is at x = 0 and whose tail is closed at x = L, its belly a
// flat strip on the ground plane z = -zb, and a rigid apple in its mouth.
// The tube's lumen is wider than the apple in the mouth (no contact at the
// start), narrows over a cone and runs narrower than the apple to near the
// tail, so that the apple, pushed toward the tail, widens the snake.
// gmsh, OpenCASCADE.
//
// Physical volumes: 1 the snake, 2 the apple.
// Physical surfaces: 1 the mouth's end face (x = 0, held), 2 the belly
// (z = -zb, moves in the ground plane), 3 the lumen (contact surface),
// 4 the outer skin, 5 the apple's surface (contact surface).
//
// Mesh size: h away from the lumen, h_in on the lumen, h_apple in the
// apple (defaults h 0.02, h_in 0.008, h_apple = h_in: 6 230
// tetrahedra; the suite's h 0.025, h_in 0.011: 3 239).
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.02;
EndIf
If (!Exists(h_in))
  h_in = 0.008;
EndIf
If (!Exists(h_apple))
  h_apple = h_in;
EndIf

L   = 0.6;    // length, in metres
R   = 0.045;  // outer radius
zb  = 0.036;  // the belly: the section is cut at z = -zb
r_a = 0.025;  // the apple's radius
r_m = 0.0275; // the lumen's radius in the mouth (1 mm more than the apple
              // plus the chord error of the two meshed spheres)
x_m = 0.07;   // the mouth's cylinder ends here ...
x_c = 0.17;   // ... and the cone narrows the lumen to r_l here (a cone
              // 4 cm long, slope 0.31, made the apple's entry cut back 16
              // times on the suite's mesh; 10 cm long: twice)
r_l = 0.015;  // the lumen's radius behind the mouth (0.6 of the apple's)
x_l = 0.55;   // the lumen ends (the tail is solid from here)
x_0 = 0.035;  // the apple's centre at the start

// the body: a cylinder cut flat at the belly, minus the lumen
Cylinder(1) = {0, 0, 0, L, 0, 0, R};
Box(2) = {-1, -1, -1, L + 2, 2, 1 - zb};
Cylinder(3) = {0, 0, 0, x_m, 0, 0, r_m};
Cone(4) = {x_m, 0, 0, x_c - x_m, 0, 0, r_m, r_l};
Cylinder(5) = {x_c, 0, 0, x_l - x_c, 0, 0, r_l};
BooleanDifference(6) = { Volume{1}; Delete; }{ Volume{2, 3, 4, 5}; Delete; };

// the apple, apart from the snake (no shared nodes)
Sphere(10) = {x_0, 0, 0, r_a};

eps = 1e-6;
mouth() = Surface In BoundingBox{-eps, -1, -1, eps, 1, 1};
belly() = Surface In BoundingBox{-eps, -1, -zb - eps, L + eps, 1, -zb + eps};
lumen() = Surface In BoundingBox{eps, -r_m - eps, -r_m - eps,
                                 x_l + eps, r_m + eps, r_m + eps};
skin() = Abs(Boundary{ Volume{6}; });
skin() -= {mouth(), belly(), lumen()};
apple() = Abs(Boundary{ Volume{10}; });

Physical Volume(1) = {6};
Physical Volume(2) = {10};
Physical Surface(1) = {mouth()};
Physical Surface(2) = {belly()};
Physical Surface(3) = {lumen()};
Physical Surface(4) = {skin()};
Physical Surface(5) = {apple()};

// h_in on the lumen, growing to h within 2 cm; h_apple in the apple
Field[1] = Distance;
Field[1].SurfacesList = {lumen()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_in;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = 0.02;
Field[3] = Ball;
Field[3].XCenter = x_0;
Field[3].Radius = r_a + 1e-3;
Field[3].VIn = h_apple;
Field[3].VOut = 1;
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.MshFileVersion = 2.2;
