// A cube of side 1 clamped on its face x = 0: the short cantilever of the
// nearly incompressible locking test (tests/elasticity/
// incompressible_cantilever.cc, doc/theory/08-nodal-pressure.md). An
// unstructured mesh: P1 tetrahedra lock on it as Poisson's ratio approaches
// 1/2. Physical groups: volume 1 (the block), surface 1 (the clamped face
// x = 0). The parameter h is the element size:
//   gmsh -3 -format msh2 -setnumber h 0.125 block_cantilever.geo
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.125 ];
Box(1) = {0, 0, 0, 1, 1, 1};
eps = 1e-6;
Physical Volume(1) = {1};
Physical Surface(1) = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
Mesh.CharacteristicLengthMax = h;
