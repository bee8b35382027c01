// A parametric knee for the flexion scene (dissertation ch. 7, paper sec. 6).
// The Visible Human meshes are not available: every part is a simple solid of
// about human size, in metres. The leg axis is z (thigh up), the front of
// the leg is +y; the femur's shaft lies on the z axis, the tibia's at
// y = y_tib, the knee axis (through the femoral condyles' centres, along x) at y = y_cond,
// z = 0, behind the shafts as in a real femur, so that the tibia, rotated
// about it, clears the femur all the way to 150 degrees (checked with the
// bones' nodes; with the condyles under the shaft the tibial plateau swept
// through the femur from 95 degrees on).
//
// Bodies, physical volumes = material ids:
//   1 femur: a shaft, the trochlea at its lower end (a cylinder along x)
//     and two condyles (cylinders along x) behind it
//   2 tibia: a shaft with a wider plateau below the condyles and the
//     tuberosity in front
//   3 patella: an ellipsoid in front of the trochlea
//   4 patellar ligament: a cylinder from the patella's lower end to the
//     tuberosity
//   5 quadriceps tendon: from the patella's upper end up the front of the
//     femur
//   6 quadriceps muscle: in front of the femur shaft, above the tendon
//   7 skin-fat layer: the rest of a cylinder of radius R_leg around all
// Attached interfaces share their nodes (one conforming mesh): tendon-muscle,
// tendon-patella, ligament-patella, ligament-tibia and skin-fat on the tibia's
// shaft (the shin, where the skin lies on the bone). Every other interface slides
// without friction: its two sides are separate surfaces with separate nodes
// (skin-fat on femur, patella, ligament, tendon, muscle and the tibia's
// plateau and tuberosity; patella on the femur; femur on tibia).
//
// Physical surfaces = boundary ids (every boundary face has one):
//   11..17 the sliding surface of body 1..7 (for skin-fat: its inner side;
//          for the tibia: its plateau and tuberosity)
//   18 the skin's outer surface (self-contact behind the knee)
//   21 the thigh's cut (z = L_thigh: femur, muscle, skin-fat)
//   22 the shin's cut (z = -L_shin: tibia, skin-fat)
//
// The mesh size: h, h / pat_refine around the patella (default 3), and
// n_2pi elements around a full circle of a curved surface (measured with
// gmsh 4.8; both meshes pass tissue-contact's mesh checks):
//   gmsh -3 -setnumber h 0.0125 -setnumber n_2pi 8 knee.geo
//     40 295 tetrahedra, 9 900 nodes, 12 373 contact triangles: the
//     sources' scale (prm/knee_flexion.prm);
//   gmsh -3 -setnumber h 0.06 -setnumber n_2pi 5 -setnumber pat_refine 2
//     4 739 tetrahedra, 1 559 nodes: the suite's coarse knee (the count
//     hardly falls below: the skin-fat layer and the small parts need
//     their few elements across).
// The test scene/knee_mesh meshes it at h 0.04, n_2pi 5; scene/knee_flexion
// at the coarse settings above.

SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.03;
EndIf
If (!Exists(pat_refine))
  pat_refine = 3; // the element size around the patella is h / pat_refine
EndIf
If (!Exists(n_2pi))
  n_2pi = 6; // elements around a full circle of a curved surface
EndIf

R_leg   = 0.065;  // radius of the leg (skin surface), about the shaft axis
L_thigh = 0.28;   // from the knee axis up to the thigh's cut: long enough for a
                  // quadriceps that can lengthen by the patella's travel
L_shin  = 0.16;   // from the knee axis down to the shin's cut
r_femur = 0.022;  // femur shaft (axis x = y = 0), rounded at its lower end
                  // by the trochlea, a cylinder along x of the same radius
r_cond  = 0.024;  // condyles: cylinders along x, w_cond wide each, gap_c
w_cond  = 0.022;  // apart (the intercondylar notch), their axis (the knee
gap_c   = 0.008;  // axis) y_cond behind the shaft axis, as in a real femur:
y_cond  = -0.030; // so the tibia can swing round behind it to 150 degrees
r_tibia = 0.020;  // tibia shaft, its axis y_tib
y_tib   = -0.015;
r_plat  = 0.026;  // tibial plateau, t_plat thick, gap_ft below the
t_plat  = 0.010;  // condyles (cartilage and menisci are not modelled)
gap_ft  = 0.004;
a_pat   = 0.017;  // patella: semi-axes in x, y, z, gap_pf in front of the
b_pat   = 0.009;  // trochlea, its centre z_pat above the knee axis
c_pat   = 0.022;
gap_pf  = 0.003;
z_pat   = 0.020;
r_lig   = 0.006;  // patellar ligament: a cylinder of radius r_lig

// initial gap between skin-fat and the sliding parts: 0.5 mm plus the chord
// error of the cavity around the condyles (a concave wall meshed with
// n_2pi elements per circle bulges by r (1 - cos(pi / n_2pi)) into what it
// encloses: 4.6 mm at n_2pi = 5, 1.8 mm at 8), so that the meshed
// surfaces start apart and the scene starts free of stress
gap_s   = 0.0005 + 1.2 * r_cond * (1 - Cos(Pi / n_2pi));

// The sliding parts are built twice: as bodies (d = 0) and, enlarged by
// d = gap_s, as the cavity cut out of the skin-fat layer, so that the
// skin-fat touches only the tibia (to which it is attached).
Macro SlidingParts
  // femur: a shaft, the trochlea at its lower end and two condyles behind
  v1 = newv; Cylinder(v1) = {0, 0, 0, 0, 0, L_thigh + d, r_femur + d};
  w_troch = gap_c / 2 + w_cond - 0.002; // a little narrower than the
                                        // condyles: no coplanar end faces
  v4 = newv; Cylinder(v4) = {-w_troch - d, 0, 0, 2 * w_troch + 2 * d, 0, 0, r_femur + d};
  If (d == 0)
    // two condyles, the intercondylar notch between them
    v2 = newv; Cylinder(v2) = {gap_c / 2, y_cond, 0, w_cond, 0, 0, r_cond};
    v3 = newv; Cylinder(v3) = {-gap_c / 2, y_cond, 0, -w_cond, 0, 0, r_cond};
    tools() = {v2, v3, v4};
  Else
    // the cavity spans the notch: one cylinder over both condyles (the
    // skin does not reach into the notch)
    v2 = newv; Cylinder(v2) = {-gap_c / 2 - w_cond - d, y_cond, 0, gap_c + 2 * w_cond + 2 * d, 0, 0, r_cond + d};
    tools() = {v2, v4};
  EndIf
  f() = BooleanUnion{ Volume{v1}; Delete; }{ Volume{tools()}; Delete; };
  // patella: an ellipsoid
  v5 = newv; Sphere(v5) = {0, 0, 0, 1};
  Dilate {{0, 0, 0}, {a_pat + d, b_pat + d, c_pat + d}} { Volume{v5}; }
  Translate {0, y_pat, z_pat} { Volume{v5}; }
  p() = {v5};
  If (d > 0)
    // the cavity also spans the space between the patella and the femur
    // (an elliptic cylinder along y under the patella's outline, from the
    // femur's axis to the patella's centre): otherwise the skin-fat fills
    // it with slivers a fraction of a millimetre thick where the two
    // enlarged surfaces nearly meet, which the patella, pulled onto the
    // femur, crushes (the full-scale knee's Newton iterations drifted
    // there, along a direction of negative curvature, from 49 degrees on)
    v9 = newv; Cylinder(v9) = {0, 0, 0, 0, 1, 0, 1};
    Dilate {{0, 0, 0}, {a_pat + d, y_pat, c_pat + d}} { Volume{v9}; }
    Translate {0, 0, z_pat} { Volume{v9}; }
    p() += v9;
  EndIf
  // patellar ligament: a cylinder from inside the tibial tuberosity up to
  // inside the patella's lower end, clear of the trochlea
  v6 = newv; Cylinder(v6) = {0, y_lig0, z_lig0, 0, y_lig1 - y_lig0, z_lig1 - z_lig0, r_lig + d};
  l() = {v6};
  // quadriceps tendon: from the patella's upper end up to z_m
  v7 = newv; Box(v7) = {-0.012 - d, y_pat - 0.005 - d, z_pat + c_pat - 0.006 - d, 0.024 + 2 * d, 0.010 + 2 * d, z_m - (z_pat + c_pat - 0.006) + 2 * d};
  t() = {v7};
  // quadriceps muscle: in front of the femur shaft, from z_m to the cut
  v8 = newv; Box(v8) = {-0.040 - d, r_femur + 0.003 - d, z_m - d, 0.080 + 2 * d, t_mus + 2 * d, L_thigh - z_m + 2 * d};
  // its lower front edge (where it meets the tendon) rounded with an 8 mm
  // fillet: pressed into the skin-fat at about 80 degrees, a sharp 90-degree
  // edge kinks the piecewise linear material depth across its two faces and
  // the full-scale knee's Newton iterations cycled there
  yf = r_femur + 0.003 + t_mus + d;
  zb = z_m - d;
  ce() = Curve In BoundingBox{-1, yf - 1e-6, zb - 1e-6, 1, yf + 1e-6, zb + 1e-6};
  v8r() = Fillet{v8}{ce()}{0.008};
  m() = {v8r(0)};
Return

z_plat = -r_cond - gap_ft; // top of the tibial plateau
y_pat  = r_femur + gap_pf + b_pat;
z_m    = 0.06;             // tendon-muscle junction
t_mus  = 0.020;            // thickness of the muscle (front to back): 2 cm
                           // of skin-fat in front of it (with 3 cm, the
                           // muscle pressed through the skin at 109 degrees)
// the ligament's ends: in the tuberosity and in the patella
y_lig0 = y_tib + r_plat + 0.004;
z_lig0 = z_plat - t_plat - 0.010;
y_lig1 = y_pat;
z_lig1 = z_pat - c_pat + 0.004;

// tibia: plateau, shaft and, in front, the tuberosity the ligament
// attaches to
Cylinder(1000) = {0, y_tib, z_plat - t_plat, 0, 0, t_plat, r_plat};
Cylinder(1001) = {0, y_tib, -L_shin, 0, 0, L_shin + z_plat - t_plat + 0.002, r_tibia};
Box(1002) = {-0.010, y_tib, z_plat - t_plat - 0.025, 0.020, r_plat + 0.010, 0.025 + t_plat - 0.004};
tib() = BooleanUnion{ Volume{1000}; Delete; }{ Volume{1001, 1002}; Delete; };

// the bodies
d = 0;
Call SlidingParts;
femur() = f();
pat()   = p();
// the ligament and the tendon overlap the patella (and the ligament the
// plateau) where they attach: the overlaps are cut away
lig() = BooleanDifference{ Volume{l()}; Delete; }{ Volume{pat(), tib()}; };
ten() = BooleanDifference{ Volume{t()}; Delete; }{ Volume{pat()}; };
mus() = m();

// the cavity, and the skin-fat layer: the leg's cylinder minus the tibia and
// the cavity
d = gap_s;
Call SlidingParts;
// the tibia's plateau and tuberosity slide too (the skin-fat is attached
// to the shaft only): at deep flexion the skin behind the plateau must be
// free to move out of the way of the femur
c1 = newv; Cylinder(c1) = {0, y_tib, z_plat - t_plat - d, 0, 0, t_plat + 2 * d, r_plat + d};
c2 = newv; Box(c2) = {-0.010 - d, y_tib, z_plat - t_plat - 0.025 - d, 0.020 + 2 * d, r_plat + 0.010 + d, 0.025 + t_plat - 0.004 + 2 * d};
cavity() = BooleanUnion{ Volume{f()}; Delete; }{ Volume{p(), l(), t(), m(), c1, c2}; Delete; };
Cylinder(2000) = {0, 0, -L_shin, 0, 0, L_shin + L_thigh, R_leg};
skn() = BooleanDifference{ Volume{2000}; Delete; }{ Volume{cavity(), tib()}; };
Recursive Delete { Volume{cavity()}; }

// one conforming mesh for the attached parts; the femur stays apart
all() = BooleanFragments{ Volume{pat(), lig(), ten(), mus(), tib(), skn()}; Delete; }{};
vol() = {femur(0), all(4), all(0), all(1), all(2), all(3), all(5)};
// femur, tibia, patella, ligament, tendon, muscle, skin-fat
For b In {0:6}
  Physical Volume(b + 1) = {vol(b)};
EndFor

// the cuts
eps = 1e-6;
thigh() = Surface In BoundingBox{-1, -1, L_thigh - eps, 1, 1, L_thigh + eps};
shin()  = Surface In BoundingBox{-1, -1, -L_shin - eps, 1, 1, -L_shin + eps};
Physical Surface(21) = {thigh()};
Physical Surface(22) = {shin()};

// every other boundary surface of a body: a surface of its boundary that no
// other body shares and that is no cut
outer() = {};
For b In {0:6}
  mine() = Abs(Boundary{ Volume{vol(b)}; });
  free() = {};
  For i In {0:#mine()-1}
    s = mine(i);
    shared = 0;
    For c In {0:6}
      If (c != b)
        other() = Abs(Boundary{ Volume{vol(c)}; });
        For j In {0:#other()-1}
          If (other(j) == s)
            shared = 1;
          EndIf
        EndFor
      EndIf
    EndFor
    For j In {0:#thigh()-1}
      If (thigh(j) == s)
        shared = 1;
      EndIf
    EndFor
    For j In {0:#shin()-1}
      If (shin(j) == s)
        shared = 1;
      EndIf
    EndFor
    If (!shared)
      bb() = BoundingBox Surface{s};
      If (b == 6 && bb(0) < -R_leg + 1e-4)
        outer() += s; // the skin's outer surface
      Else
        free() += s;
      EndIf
    EndIf
  EndFor
  Physical Surface(11 + b) = {free()};
EndFor
Physical Surface(18) = {outer()};

// element size h, h / pat_refine around the patella and its attachments
Field[1] = Ball;
Field[1].Radius = 0.035;
Field[1].Thickness = 0.03;
Field[1].XCenter = 0;
Field[1].YCenter = y_pat;
Field[1].ZCenter = z_pat;
Field[1].VIn = h / pat_refine;
Field[1].VOut = h;
Background Field = 1;
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthFromCurvature = 1;
Mesh.MinimumElementsPerTwoPi = n_2pi;
Mesh.MshFileVersion = 2.2;
