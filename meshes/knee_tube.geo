// A knee-scale tube for the speed benchmark tests/performance/knee (issue:
// the knee-scale scene in a minute): a leg-sized sleeve of skin-fat around two
// bones, bent 150 degrees at the knee so that the skin behind the knee folds
// onto itself. It has the knee's size and contact load (about 40 000
// tetrahedra, 10 000 nodes, 10 000 self-contact triangles at the default h)
// without its many bodies, and it runs to the end.
//
// The leg axis is z (thigh up, z > 0), the front is +y, the knee axis is x
// through the origin. The bones are not meshed: they are rigid and bonded to
// the sleeve, so their surfaces are Dirichlet boundaries (bores in the
// sleeve, each a cylinder with a rounded end at the knee):
//   1 femur bore (z > z_end, fixed)
//   2 tibia bore (z < -z_end, rotated about the knee axis)
//   3 the skin's outer surface (self-contact)
//   4 the thigh's cut (z = L: moves only in its plane)
//   5 the shin's cut (z = -L: free)
// Physical volume 1: the sleeve (one body).
//
//   gmsh -3 -setnumber h 0.0062 knee_tube.geo
//     (the benchmark's mesh; h 0.012 meshes a quick version)
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.0062;
EndIf
R_leg  = 0.05;   // outer radius of the sleeve
R_bone = 0.03;   // radius of the bones
L      = 0.2;    // length of the thigh and of the shin
z_end  = 0.045;  // the bones' rounded ends are at z = +-z_end

Cylinder(1) = {0, 0, -L, 0, 0, 2 * L, R_leg};
Cylinder(2) = {0, 0, z_end, 0, 0, L, R_bone};
Sphere(3)   = {0, 0, z_end, R_bone};
Cylinder(4) = {0, 0, -L - z_end, 0, 0, L, R_bone};
Sphere(5)   = {0, 0, -z_end, R_bone};
BooleanUnion(6) = { Volume{2}; Delete; }{ Volume{3}; Delete; };
BooleanUnion(7) = { Volume{4}; Delete; }{ Volume{5}; Delete; };
BooleanDifference(8) = { Volume{1}; Delete; }{ Volume{6, 7}; Delete; };

Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = h;
Mesh.Optimize = 1;

eps = 1e-6;
Physical Volume(1) = {8};
Physical Surface(1) = Surface In BoundingBox{-R_bone - eps, -R_bone - eps, z_end - R_bone - eps,
                                             R_bone + eps, R_bone + eps, L - eps};
Physical Surface(2) = Surface In BoundingBox{-R_bone - eps, -R_bone - eps, -L + eps,
                                             R_bone + eps, R_bone + eps, -z_end + R_bone + eps};
Physical Surface(4) = Surface In BoundingBox{-R_leg - eps, -R_leg - eps, L - eps,
                                             R_leg + eps, R_leg + eps, L + eps};
Physical Surface(5) = Surface In BoundingBox{-R_leg - eps, -R_leg - eps, -L - eps,
                                             R_leg + eps, R_leg + eps, -L + eps};
all() = Surface{:};
Physical Surface(3) = {all()};
Physical Surface(3) -= {Surface In BoundingBox{-R_bone - eps, -R_bone - eps, -L - eps,
                                               R_bone + eps, R_bone + eps, L + eps}};
Physical Surface(3) -= {Surface In BoundingBox{-R_leg - eps, -R_leg - eps, L - eps,
                                               R_leg + eps, R_leg + eps, L + eps}};
Physical Surface(3) -= {Surface In BoundingBox{-R_leg - eps, -R_leg - eps, -L - eps,
                                               R_leg + eps, R_leg + eps, -L + eps}};
