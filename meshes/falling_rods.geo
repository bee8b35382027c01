// Dissertation 8.2 (Fig. 51): an array of rods mounted on a 45 degree
// slanted foundation, falling under gravity onto a curved bar below them.
//
// The foundation is the half-space x + z < 0 (its face rises from the
// ground z = 0 towards -x; both are analytic planes in the prm). Each rod
// is a cylinder of radius r and length L along n = (1, 0, 1)/sqrt(2),
// clamped where it meets the slope: row i (0 the lowest) sits s0 + i*sr
// up the slope, column j at y = (j - (nc-1)/2)*sc + (i - (nr-1)/2)*skew
// (the skew makes the array "slightly skewed rather than completely
// rectangular", as in the dissertation). The curved bar is a torus
// segment of tube radius rb whose core arches in the plane of e_y and the
// up-slope direction: its apex sits gap below the lowest row's axis at
// 0.75 L along the rods, and it bends away from the rods with radius Rb,
// so the middle rods hit it first.
//
// Physical volumes: 1 the rods (one body: rod-rod contact is its
// self-contact), 2 the bar (rigid in the prm). Physical surfaces: 1 the
// clamped ends, 2 the other rod faces, 3 the bar.
//
//   gmsh -3 -format msh2 -setnumber lc_bar 0.05 falling_rods.geo -o falling_rods.msh
//   gmsh -3 -format msh2 -setnumber nr 2 -setnumber nc 2 -setnumber lc 0.08
//        falling_rods.geo -o falling_rods_2x2.msh
SetFactory("OpenCASCADE");
DefineConstant[ nc = 7, nr = 5, lc = 0.05, lc_bar = 0.1 ];
L = 1; r = 0.06; s0 = 0.3; sr = 0.25; sc = 0.25; skew = 0.06;
rb = 0.08; gap = 0.2; Rb = 2;
c = Sqrt(0.5);
rods[] = {};
axes[] = {};
bases[] = {};
For i In {0:nr - 1}
  For j In {0:nc - 1}
    s = s0 + i * sr;
    y = (j - (nc - 1) / 2) * sc + (i - (nr - 1) / 2) * skew;
    v = newv;
    Cylinder(v) = {-s * c, y, s * c, L * c, 0, L * c, r};
    rods[] += v;
    bases[] += {-s * c, y, s * c};
    // the axis (short of the end faces) embedded: interior vertices, so
    // that the material depth (a vertex field) is r on it, not zero
    p1 = newp; Point(p1) = {(-s + r) * c, y, (s + r) * c};
    p2 = newp; Point(p2) = {(-s + L - r) * c, y, (s + L - r) * c};
    l = newl; Line(l) = {p1, p2};
    axes[] += l;
  EndFor
EndFor

// the bar: a torus about the z axis (core radius Rb, tube rb), cut to the
// arc that spans the array plus a margin, turned so that its core lies in
// the plane of e_y and t = (-1, 0, 1)/sqrt(2) with the apex at P0
half_width = (nc - 1) / 2 * sc + (nr - 1) / 2 * skew + 2 * r + 0.15;
phi = 2 * Asin(half_width / Rb);
bar = newv;
Torus(bar) = {0, 0, 0, Rb, rb, phi};
core = newl;
Circle(core) = {0, 0, 0, Rb, rb / Rb, phi - rb / Rb};
// the arc runs from angle 0 to phi in the xy plane: centre it on the x axis
Rotate{{0, 0, 1}, {0, 0, 0}, -phi / 2} { Volume{bar}; Curve{core}; }
// core plane: x -> t = (-1, 0, 1)/sqrt(2) (towards the rods), y -> e_y,
// z -> -n: a rotation by -3 pi / 4 about e_y; the apex is then at Rb t
Rotate{{0, 1, 0}, {0, 0, 0}, -3 * Pi / 4} { Volume{bar}; Curve{core}; }
s = s0;
P0[] = {-s * c + 0.75 * L * c + gap * c, 0, s * c + 0.75 * L * c - gap * c};
Translate{P0[0] + Rb * c, 0, P0[2] - Rb * c} { Volume{bar}; Curve{core}; }

For k In {0:#rods[] - 1}
  Curve{axes[k]} In Volume{rods[k]};
EndFor
Curve{core} In Volume{bar};
MeshSize{ PointsOf{ Volume{rods[]}; Curve{axes[]}; } } = lc;
MeshSize{ PointsOf{ Curve{core}; } } = lc_bar;
MeshSize{ PointsOf{ Volume{bar}; Curve{core}; } } = lc_bar;

Physical Volume(1) = {rods[]};
Physical Volume(2) = {bar};
eps = 1e-6;
clamped[] = {};
For k In {0:#rods[] - 1}
  bx = bases[3 * k]; by = bases[3 * k + 1]; bz = bases[3 * k + 2];
  clamped[] += Surface In BoundingBox{bx - r - eps, by - r - eps, bz - r - eps,
                                      bx + r + eps, by + r + eps, bz + r + eps};
EndFor
Physical Surface(1) = {clamped[]};
rod_faces[] = Boundary{ Volume{rods[]}; };
Physical Surface(2) = {rod_faces[]};
Physical Surface(2) -= {clamped[]};
Physical Surface(3) = Boundary{ Volume{bar}; Curve{core}; };
