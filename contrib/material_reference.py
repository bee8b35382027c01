#!/usr/bin/env python3
"""Independent reference values for tests/materials/material_derivatives.

Each model's strain energy Psi is written here from doc/theory/03-materials.md
as a function of the nine entries of F, and differentiated symbolically
(sympy): P = dPsi/dF and A = d^2 Psi / dF dF, evaluated at one fixed F with
40 significant digits. The code computes the same quantities through S, C
and a push-forward, so agreement checks the derivation, not only the code's
self-consistency. Prints C++ initializers that the test embeds:
Psi, P (row by row), |A| (Frobenius) and G : A : H for two fixed tensors.

    python3 contrib/material_reference.py     # needs sympy (Debian: python3-sympy)
    python3 contrib/material_reference.py --uncoupled   # only sec. 3.7's forms
"""
import sympy as sp

Fs = sp.Matrix(3, 3, sp.symbols("F0:9"))
C = Fs.T * Fs
I1 = C.trace()
I2 = (I1**2 - (C * C).trace()) / 2
I3 = C.det()
E = (C - sp.eye(3)) / 2
eps = (Fs + Fs.T) / 2 - sp.eye(3)

F_value = sp.Matrix([[sp.Rational(11, 10), sp.Rational(2, 10), sp.Rational(-1, 10)],
                     [sp.Rational(5, 100), sp.Rational(9, 10), sp.Rational(15, 100)],
                     [sp.Rational(-12, 100), sp.Rational(8, 100), sp.Rational(105, 100)]])
G = sp.Matrix([[1, 2, 0], [0, -1, 3], [1, 0, 1]])
H = sp.Matrix([[0, 1, -1], [2, 1, 0], [0, 3, 1]])


def neo_hooke(mu, lam):
    return mu / 2 * (I1 - 3) - mu / 2 * sp.log(I3) + lam / 8 * sp.log(I3)**2


def mooney_rivlin(C1, C2, a):
    k = C1 + 2 * C2 + a
    return C1 * (I1 - 3) + C2 * (I2 - 3) + a * (I3 - 1) - k * sp.log(I3)


def veronda(alpha, beta, a):
    return (alpha * (sp.exp(beta * (I1 - 3)) - 1) - alpha * beta / 2 * (I2 - 3)
            + a * (I3 - 1) - a * sp.log(I3))


def svk(mu, lam):
    return lam / 2 * E.trace()**2 + mu * (E * E).trace()


def linear(mu, lam):
    return lam / 2 * eps.trace()**2 + mu * (eps * eps).trace()


def fiber(alpha, beta, f):
    f = sp.Matrix(f) / sp.sqrt(sum(c**2 for c in f))
    l2 = (f.T * C * f)[0]
    return alpha * (sp.exp(beta * (l2 - 1)) - 1) - alpha * beta * (l2 - 1)


# the uncoupled forms (doc/theory/03-materials.md sec. 3.7): Psi_bar of the
# invariants of F_bar = J^(-1/3) F with J = det F, plus
# U = kappa/4 (J^2 - 1 - 2 ln J); no chain rule (M9)-(M10) here
J = Fs.det()
I1_bar = I1 * J**sp.Rational(-2, 3)
I2_bar = I2 * J**sp.Rational(-4, 3)


def volumetric(kappa):
    return kappa / 4 * (J**2 - 1 - 2 * sp.log(J))


def uncoupled_neo_hooke(mu, kappa):
    return mu / 2 * (I1_bar - 3) + volumetric(kappa)


def uncoupled_mooney_rivlin(C1, C2, kappa):
    return C1 * (I1_bar - 3) + C2 * (I2_bar - 3) + volumetric(kappa)


def uncoupled_veronda(alpha, beta, kappa):
    return (alpha * (sp.exp(beta * (I1_bar - 3)) - 1)
            - alpha * beta / 2 * (I2_bar - 3) + volumetric(kappa))


Z = sp.Integer  # exact constants: no binary floating point before evaluation
models = [
    ("neo-Hookean(3, 5)", neo_hooke(Z(3), Z(5))),
    ("Mooney-Rivlin(5, 1, 50)", mooney_rivlin(Z(5), Z(1), Z(50))),
    ("Veronda(7, 8, 100)", veronda(Z(7), Z(8), Z(100))),
    ("Saint Venant-Kirchhoff(3, 5)", svk(Z(3), Z(5))),
    ("linear(3, 5)", linear(Z(3), Z(5))),
    ("Mooney-Rivlin(5, 1, 50) + fiber(2, 3, e_x)",
     mooney_rivlin(Z(5), Z(1), Z(50)) + fiber(Z(2), Z(3), [1, 0, 0])),
    ("uncoupled neo-Hookean(3, 50)", uncoupled_neo_hooke(Z(3), Z(50))),
    ("uncoupled Mooney-Rivlin(5, 1, 60)",
     uncoupled_mooney_rivlin(Z(5), Z(1), Z(60))),
    ("uncoupled Veronda(7, 8, 500)", uncoupled_veronda(Z(7), Z(8), Z(500))),
]
import sys
only_uncoupled = sys.argv[1:] == ["--uncoupled"]
if only_uncoupled:
    models = [m for m in models if m[0].startswith("uncoupled")]

subs = dict(zip(Fs, F_value))
for name, psi in models:
    P = [sp.diff(psi, Fs[i]) for i in range(9)]
    A = [[sp.diff(P[i], Fs[j]) for j in range(9)] for i in range(9)]
    psi_v = sp.N(psi.subs(subs), 40)
    P_v = [sp.N(p.subs(subs), 40) for p in P]
    A_v = [[sp.N(a.subs(subs), 40) for a in row] for row in A]
    norm_A = sp.sqrt(sum(a**2 for row in A_v for a in row))
    GAH = sum(G[i // 3, i % 3] * A_v[i][j] * H[j // 3, j % 3]
              for i in range(9) for j in range(9))
    fmt = lambda x: "%.17g" % float(x)
    print("  // %s" % name)
    print("  {%s, {%s}, %s, %s}," % (fmt(psi_v), ", ".join(fmt(p) for p in P_v),
                                      fmt(norm_A), fmt(GAH)))

if only_uncoupled:
    sys.exit(0)

# Corotated(3, 5) (doc/theory/03-materials.md sec. 3.6): Psi = mu |U - I|^2
# + lam/2 (tr U - 3)^2 with U = sqrt(C) has no closed form in F that sympy
# differentiates usefully, so it is evaluated in 60-digit arithmetic without
# the code's derivation: tr U is the largest root of the quartic
# x^4 - 2 I1 x^2 - 8 sqrt(I3) x + I1^2 - 4 I2 = 0 (from I1 = i1^2 - 2 i2,
# I2 = i2^2 - 2 i1 i3, I3 = i3^2 for the invariants i of U), |U - I|^2 =
# I1 - 2 tr U + 3, and P, A are central differences with step 1e-22
# (truncation error 1e-44).
import mpmath as mp

mp.mp.dps = 60


def corotated_psi(F, mu=3, lam=5):
    Fm = mp.matrix(F)
    Cm = Fm.T * Fm
    i1_C = Cm[0, 0] + Cm[1, 1] + Cm[2, 2]
    tr_C2 = sum(Cm[i, j] * Cm[j, i] for i in range(3) for j in range(3))
    i2_C = (i1_C**2 - tr_C2) / 2
    i3_C = mp.det(Cm)
    roots = mp.polyroots([1, 0, -2 * i1_C, -8 * mp.sqrt(i3_C), i1_C**2 - 4 * i2_C],
                         maxsteps=200, extraprec=200)
    trU = max(mp.re(r) for r in roots if abs(mp.im(r)) < mp.mpf(10)**-40)
    return mu * (i1_C - 2 * trU + 3) + mp.mpf(lam) / 2 * (trU - 3)**2


F0 = [[mp.mpf(str(F_value[i, j].p)) / F_value[i, j].q for j in range(3)]
      for i in range(3)]
h = mp.mpf(10)**-22


def shifted(F, moves):
    G_ = [row[:] for row in F]
    for (i, j), d in moves:
        G_[i][j] += d
    return G_


P_c = [(corotated_psi(shifted(F0, [((i // 3, i % 3), h)]))
        - corotated_psi(shifted(F0, [((i // 3, i % 3), -h)]))) / (2 * h)
       for i in range(9)]
A_c = [[(corotated_psi(shifted(F0, [((i // 3, i % 3), h), ((j // 3, j % 3), h)]))
         - corotated_psi(shifted(F0, [((i // 3, i % 3), h), ((j // 3, j % 3), -h)]))
         - corotated_psi(shifted(F0, [((i // 3, i % 3), -h), ((j // 3, j % 3), h)]))
         + corotated_psi(shifted(F0, [((i // 3, i % 3), -h), ((j // 3, j % 3), -h)])))
        / (4 * h * h) for j in range(9)] for i in range(9)]
norm_A = mp.sqrt(sum(a**2 for row in A_c for a in row))
GAH = sum(int(G[i // 3, i % 3]) * A_c[i][j] * int(H[j // 3, j % 3])
          for i in range(9) for j in range(9))
fmt = lambda x: "%.17g" % float(x)
print("  // corotated(3, 5)")
print("  {%s, {%s}, %s, %s}," % (fmt(corotated_psi(F0)), ", ".join(fmt(p) for p in P_c),
                                  fmt(norm_A), fmt(GAH)))
