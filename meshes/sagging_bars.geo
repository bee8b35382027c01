// Paper Fig. 13: elastic bars deformed by their own weight. Three
// cantilevers side by side, 1 long with a 0.1 x 0.1 section, 0.2 apart in y;
// each its own body (material ids 1, 2, 3: the prm gives them different
// stiffness). Boundary ids: 1 the clamped faces x = 0, 2 all other faces.
//   gmsh -3 -format msh2 -setnumber lc 0.1 sagging_bars.geo -o sagging_bars.msh
SetFactory("OpenCASCADE");
DefineConstant[ lc = 0.1 ];
For i In {0:2}
  Box(i + 1) = {0, 0.2 * i, 0, 1, 0.1, 0.1};
EndFor
MeshSize{ PointsOf{ Volume{1, 2, 3}; } } = lc;
eps = 1e-6;
Physical Volume(1) = {1};
Physical Volume(2) = {2};
Physical Volume(3) = {3};
clamped[] = Surface In BoundingBox{-eps, -eps, -eps, eps, 1, 0.1 + eps};
Physical Surface(1) = {clamped[]};
all[] = Surface{:};
Physical Surface(2) = {all[]};
Physical Surface(2) -= {clamped[]};
