// A bar of two materials in series: [0,1] x [0,1]^2 is material 1,
// [1,2] x [0,1]^2 material 2, conforming at x = 1 (shared nodes).
// Boundary ids: 1 the face x = 0, 2 the face x = 2, 3 the faces y = 0,
// 4 the faces z = 0, 5 the other faces.
SetFactory("OpenCASCADE");
lc = 0.5;
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
BooleanFragments{ Volume{1, 2}; Delete; }{}
Mesh.CharacteristicLengthMax = lc;
Physical Volume(1) = {1};
Physical Volume(2) = {2};
eps = 1e-6;
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Physical Surface(2) = Surface In BoundingBox{2 - eps, -eps, -eps, 2 + eps, 1 + eps, 1 + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, -eps, 2 + eps, eps, 1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, -eps, -eps, 2 + eps, 1 + eps, eps};
Physical Surface(5) = Surface In BoundingBox{-eps, 1 - eps, -eps, 2 + eps, 1 + eps, 1 + eps};
Physical Surface(5) += Surface In BoundingBox{-eps, -eps, 1 - eps, 2 + eps, 1 + eps, 1 + eps};
