// Two separate blocks, not conforming: a lower block (material id 1,
// [0,1] x [0,1] x [0,0.5]) and an upper block (material id 2,
// [0,1] x [0,1] x [0.5 - overlap, 1 - overlap]) meshed with different element
// sizes, so their nodes do not match at the interface.
// Boundary ids: 1 bottom of the lower block, 2 top of the upper block,
// 3 bottom of the upper block (a contact surface), 4 top of the lower block
// (a contact surface), 5 the lower block's sides, 6 the upper block's sides.
//   gmsh -3 -format msh2 stacked_blocks.geo -o stacked_blocks.msh
SetFactory("OpenCASCADE");
DefineConstant[ lower = 0.34, upper = 0.26, overlap = 0.002 ];
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5 - overlap, 1, 1, 0.5};
eps = 1e-6;
MeshSize{ PointsOf{ Volume{1}; } } = lower;
MeshSize{ PointsOf{ Volume{2}; } } = upper;
z1 = 0.5 - overlap;
Physical Volume(1) = {1};
Physical Volume(2) = {2};
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
Physical Surface(2) = Surface In BoundingBox{-eps, -eps, 1 - overlap - eps, 1 + eps, 1 + eps, 1 - overlap + eps};
Physical Surface(3) = Surface In BoundingBox{-eps, -eps, z1 - eps, 1 + eps, 1 + eps, z1 + eps};
Physical Surface(4) = Surface In BoundingBox{-eps, -eps, 0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps};
lower_all() = Abs(Boundary{ Volume{1}; });
upper_all() = Abs(Boundary{ Volume{2}; });
Physical Surface(5) = {lower_all(0), lower_all(1), lower_all(2), lower_all(3)};
Physical Surface(6) = {upper_all(0), upper_all(1), upper_all(2), upper_all(3)};
