// A block of muscle (material id 1) under a layer of skin-fat (material id 2),
// conforming at the interface. Boundary ids: 1 bottom (z = 0), 2 top
// (z = 0.3), 3 the sides.
//   gmsh -3 -format msh2 layered_block.geo -o layered_block.msh
SetFactory("OpenCASCADE");
DefineConstant[ lc = 0.1 ]; // element size; override with: gmsh -setnumber lc 0.2
Box(1) = {0, 0, 0, 1, 0.5, 0.25};
Box(2) = {0, 0, 0.25, 1, 0.5, 0.05};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = lc;
eps = 1e-6;
bottom() = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 0.5 + eps, eps};
top()    = Surface In BoundingBox{-eps, -eps, 0.3 - eps, 1 + eps, 0.5 + eps, 0.3 + eps};
all()    = Abs(CombinedBoundary{ Volume{1, 2}; });
sides()  = {};
For i In {0 : #all() - 1}
  s = all(i);
  If (s != bottom(0) && s != top(0))
    sides() += s;
  EndIf
EndFor
Physical Volume(1) = {1};
Physical Volume(2) = {2};
Physical Surface(1) = bottom();
Physical Surface(2) = top();
Physical Surface(3) = sides();
