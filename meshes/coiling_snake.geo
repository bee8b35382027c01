// The coiling snake (dissertation 8.1): a tube of circular section, its
// tail at x = 0, its head at x = L. gmsh, OpenCASCADE.
// Physical volume 1: the snake. Physical surfaces: 1 the tail's end face
// (x = 0), 2 the head's end face (x = L), 3 the skin (contact surface).
// Mesh size h (default 0.02: 1 143 tetrahedra; h 0.01: about 8 000).
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.02;
EndIf
L = 0.6;  // length, in metres
r = 0.02; // radius
Cylinder(1) = {0, 0, 0, L, 0, 0, r};
Mesh.CharacteristicLengthMax = h;
Mesh.MinimumElementsPerTwoPi = 8;
Mesh.MshFileVersion = 2.2;
Physical Volume(1) = {1};
eps = 1e-6;
tail() = Surface In BoundingBox{-eps, -1, -1, eps, 1, 1};
head() = Surface In BoundingBox{L - eps, -1, -1, L + eps, 1, 1};
side() = Abs(Boundary{ Volume{1}; });
side() -= {tail(), head()};
Physical Surface(1) = {tail()};
Physical Surface(2) = {head()};
Physical Surface(3) = {side()};
