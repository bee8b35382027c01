#!/usr/bin/python3
"""The locking-free reference of tests/elasticity/incompressible_cantilever
(a peer computation, not a test): the nearly incompressible short
cantilever solved by FEniCSx (Debian's python3-dolfinx) with a mixed
element that does not lock, on a sequence of meshes.

The block [0, 1]^3 is clamped on x = 0 and loaded by its own weight
(density 1, gravity 100 in -z); the material is TissueContact's uncoupled
neo-Hookean (doc/theory/03-materials.md sec. 3.7) with mu = 1000 and
kappa = 4 999 666.7 (Poisson's ratio 0.4999):

    Psi = mu/2 (J^(-2/3) tr C - 3) + kappa/4 (J^2 - 1 - 2 ln J).

FEniCSx solves the three-field (Hu-Washizu) form of the same energy,

    Pi(u, J~, p) = int Psi_iso(F) + U(J~) + p (det F - J~) dV - W_ext(u),

with u in P2 and J~, p in P1 (continuous): Taylor-Hood for the pressure,
stable as the bulk modulus grows. At stationarity J~ -> det F and
p -> U'(det F) as the mesh is refined, so the continuum solution is the
displacement-only one's. The load is applied in 8 equal increments, each
solved by Newton with MUMPS to 1e-10. Printed per mesh (n x n x n cubes of
six tetrahedra): unknowns, Newton iterations, the strain energy
int Psi_iso + U(J~) dV and the load's work, then the energy extrapolated
to h = 0 with the order observed on the three meshes: the reference the test
compares with.

    /usr/bin/python3 tests/performance/peer_incompressible.py [--quick]

--quick runs n = 4 and 8 only (half a minute, no extrapolation); the
default adds n = 12 (15 minutes on two cores). Needs python3-dolfinx; prints a note and
exits 0 without it.
"""

import sys
import time

MU, KAPPA, RHO, G = 1000.0, 4999666.7, 1.0, 100.0
INCREMENTS = 8


def solve(n):
    import numpy as np
    import ufl
    from dolfinx import fem, mesh
    from dolfinx.fem.petsc import NonlinearProblem
    from dolfinx.nls.petsc import NewtonSolver
    from mpi4py import MPI
    from petsc4py import PETSc

    start = time.time()
    msh = mesh.create_box(
        MPI.COMM_WORLD,
        [np.zeros(3), np.ones(3)],
        [n, n, n],
        mesh.CellType.tetrahedron,
    )
    cell = msh.ufl_cell()
    element = ufl.MixedElement(
        [
            ufl.VectorElement("Lagrange", cell, 2),
            ufl.FiniteElement("Lagrange", cell, 1),
            ufl.FiniteElement("Lagrange", cell, 1),
        ]
    )
    V = fem.FunctionSpace(msh, element)
    w = fem.Function(V)
    u, J_tilde, p = ufl.split(w)

    V_u, _ = V.sub(0).collapse()
    clamped = mesh.locate_entities_boundary(
        msh, 2, lambda x: np.isclose(x[0], 0.0)
    )
    dofs = fem.locate_dofs_topological((V.sub(0), V_u), 2, clamped)
    bc = fem.dirichletbc(fem.Function(V_u), dofs, V.sub(0))
    _, J_dofs = V.sub(1).collapse()
    w.x.array[J_dofs] = 1.0  # J~ = 1 at rest (U has ln J~)

    load = fem.Constant(msh, PETSc.ScalarType(0.0))
    F = ufl.Identity(3) + ufl.grad(u)
    J = ufl.det(F)
    psi_iso = MU / 2 * (J ** (-2.0 / 3.0) * ufl.tr(F.T * F) - 3)
    U = KAPPA / 4 * (J_tilde**2 - 1 - 2 * ufl.ln(J_tilde))
    body = ufl.as_vector([0.0, 0.0, -RHO * G])
    Pi = (psi_iso + U + p * (J - J_tilde)) * ufl.dx - load * ufl.inner(
        body, u
    ) * ufl.dx
    R = ufl.derivative(Pi, w, ufl.TestFunction(V))
    K = ufl.derivative(R, w, ufl.TrialFunction(V))
    solver = NewtonSolver(MPI.COMM_WORLD, NonlinearProblem(R, w, [bc], J=K))
    solver.rtol = solver.atol = 1e-10
    solver.max_it = 50
    ksp = solver.krylov_solver
    options = PETSc.Options()
    prefix = ksp.getOptionsPrefix()
    options[f"{prefix}ksp_type"] = "preonly"
    options[f"{prefix}pc_type"] = "lu"
    options[f"{prefix}pc_factor_mat_solver_type"] = "mumps"
    ksp.setFromOptions()
    newton = 0
    for k in range(1, INCREMENTS + 1):
        load.value = k / INCREMENTS
        newton += solver.solve(w)[0]
    energy = fem.assemble_scalar(fem.form((psi_iso + U) * ufl.dx))
    work = fem.assemble_scalar(fem.form(ufl.inner(body, u) * ufl.dx))
    unknowns = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    print(
        f"n = {n:2d}: {unknowns:6d} unknowns, {newton} Newton iterations, "
        f"strain energy {energy:.6f}, work of the weight {work:.6f}, "
        f"{time.time() - start:.0f} s",
        flush=True,
    )
    return energy


def main():
    try:
        import dolfinx  # noqa: F401
    except ImportError:
        print("python3-dolfinx is not installed: nothing to compare with")
        return 0
    sizes = [4, 8] if "--quick" in sys.argv else [4, 8, 12]
    energies = [solve(n) for n in sizes]
    if len(sizes) < 3:
        return 0
    # the energy converges as h^p, p below Taylor-Hood's 4 for a smooth
    # solution (the clamped edges are singular): fit p to the three meshes,
    # (e8 - e4) / (e12 - e8) = (h4^p - h8^p) / (h8^p - h12^p), by bisection,
    # then extrapolate from the finest two
    h = [1.0 / n for n in sizes]
    e = energies
    ratio = (e[1] - e[0]) / (e[2] - e[1])
    low, high = 0.1, 8.0
    for _ in range(100):
        p = 0.5 * (low + high)
        r = (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p)
        low, high = (p, high) if r < ratio else (low, p)
    extrapolated = e[2] + (e[2] - e[1]) * h[2] ** p / (h[1] ** p - h[2] ** p)
    print(f"observed order of the energy: {p:.2f}; extrapolated strain "
          f"energy: {extrapolated:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
