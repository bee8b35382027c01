// A C-shaped body (material id 1): a block with a slot open at x = 1, so
// that pressing the upper arm down closes the slot and the arm meets the
// lower one (self-contact). Boundary ids: 1 bottom (y = 0), 2 top (y = 1),
// 3 the faces of the slot (the contact surface); all other faces get 0.
//   gmsh -3 -format msh2 pinched_tube.geo -o pinched_tube.msh
SetFactory("OpenCASCADE");
DefineConstant[ lc = 0.12 ];
Box(1) = {0, 0, 0, 1, 1, 0.4};
Box(2) = {0.3, 0.35, -0.1, 0.8, 0.3, 0.6};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = lc;
eps = 1e-6;
Physical Volume(1) = {3};
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, 0.4 + eps};
Physical Surface(2) = Surface In BoundingBox{-eps, 1 - eps, -eps, 1 + eps, 1 + eps, 0.4 + eps};
Physical Surface(3) = Surface In BoundingBox{0.3 - eps, 0.35 - eps, -eps, 1 + eps, 0.65 + eps, 0.4 + eps};
