#!/usr/bin/python3
"""A peer side by side (benchmark, not a test): the same clamped
Mooney-Rivlin beam, the same gmsh mesh and the same strain energy in
TissueContact and in FEniCSx (Debian's python3-dolfinx), at three sizes.

The beam is 1 x 0.1 x 0.1, clamped at x = 0 and bent by its own weight
(density 1000, g = 0.5 in -z: the tip sags about 0.2); Mooney-Rivlin C1 = 5e4, C2 = 1e4, a = 5e5
(doc/theory/03-materials.md):

    W = C1 (I1 - 3) + C2 (I2 - 3) + a (I3 - 1) - (C1 + 2 C2 + a) ln I3.

Both codes load it in the same 4 increments, solve each with Newton and a
direct solver (MUMPS in both) to a residual of 1e-10 of the applied load,
and report the displacement of the tip's corner vertex (1, 0, 0), which
must agree to 1e-10, the Newton iterations, the wall time of assembly
(residual + tangent) and of the linear solves, and their ratios. P1
tetrahedra: the deformation gradient is constant per cell, so one
quadrature point is exact in both codes and the discrete energies are the
same function of the nodal displacements.

    cmake --build build --target performance
    /usr/bin/python3 tests/performance/peer_fenicsx.py [--quick]

Needs python3-dolfinx and python3-gmsh (Debian); prints a note and exits 0
without them. --quick runs only the smallest size.
"""

import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DRIVER = os.path.join(ROOT, "build", "tests", "performance", "peer_beam")

C1, C2, A = 5e4, 1e4, 5e5
RHO, G = 1000.0, 0.5
L, W, H = 1.0, 0.1, 0.1
INCREMENTS = 4
TOLERANCE = 1e-10
TIP = (L, 0.0, 0.0)


def make_mesh(h, path):
    """The beam meshed by gmsh with element size h: physical volume 1,
    physical surface 1 the clamped face x = 0."""
    import gmsh

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("beam")
    gmsh.model.occ.addBox(0, 0, 0, L, W, H)
    gmsh.model.occ.synchronize()
    clamped = [
        s[1]
        for s in gmsh.model.getEntities(2)
        if abs(gmsh.model.occ.getCenterOfMass(2, s[1])[0]) < 1e-9
    ]
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.model.addPhysicalGroup(2, clamped, 1)
    gmsh.option.setNumber("Mesh.CharacteristicLengthMax", h)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.model.mesh.generate(3)
    n_tets = len(gmsh.model.mesh.getElementsByType(4)[0])
    gmsh.write(path)
    gmsh.finalize()
    return n_tets


def write_prm(mesh, path, out_dir):
    with open(path, "w") as f:
        f.write(
            f"""subsection Mesh
  set Source = file
  set File   = {mesh}
end
subsection Bodies
  subsection Body 0
    set Material id = 1
    set Model       = Mooney-Rivlin
    set C1          = {C1}
    set C2          = {C2}
    set a           = {A}
    set Density     = {RHO}
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 1
  subsection Dirichlet 0
    set Boundary id = 1
  end
end
subsection Loads
  set Gravity = 0, 0, {-G}
end
subsection Load stepping
  set Initial increment = {1.0 / INCREMENTS}
  set Maximum increment = {1.0 / INCREMENTS}
  set Minimum increment = {1.0 / INCREMENTS}
end
subsection Newton
  set Residual tolerance = {TOLERANCE}
  set Line search        = energy
  set Maximum iterations = 30
end
subsection Linear solver
  set Type          = direct
  set Direct solver = MUMPS
end
subsection Output
  set Directory    = {out_dir}
  set Write VTU    = false
  set Print timing = false
end
"""
        )


def run_ours(prm):
    run = subprocess.run(
        [DRIVER, prm] + [str(c) for c in TIP],
        capture_output=True,
        text=True,
        env=dict(os.environ, DEAL_II_NUM_THREADS="1"),
    )
    if run.returncode != 0:
        raise RuntimeError("TissueContact: " + run.stderr.strip())
    out = run.stdout
    values = {}
    for line in out.splitlines():
        key, *rest = line.split()
        values[key] = [float(v) for v in rest]
    return {
        "unknowns": int(values["unknowns"][0]),
        "newton": int(values["newton_iterations"][0]),
        "assembly": values["assembly_seconds"][0],
        "solve": values["solve_seconds"][0],
        "tip": values["displacement"],
        "vertex": values["vertex"],
    }


def run_fenicsx(mesh_file):
    import numpy as np
    import ufl
    from dolfinx import fem, geometry
    from dolfinx.io import gmshio
    from mpi4py import MPI
    from petsc4py import PETSc
    import dolfinx.fem.petsc  # noqa: F401 (fem.petsc)

    # gmshio.read_from_msh of Debian's dolfinx 0.5.2 returns an undefined
    # name: the file is read into a gmsh model here instead
    import gmsh

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.merge(mesh_file)
    mesh, _, facet_tags = gmshio.model_to_mesh(gmsh.model, MPI.COMM_WORLD, 0, gdim=3)
    gmsh.finalize()
    V = fem.VectorFunctionSpace(mesh, ("Lagrange", 1))
    clamped = fem.locate_dofs_topological(V, 2, facet_tags.find(1))
    bc = fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamped, V)
    # the clamped nodes' three entries each (V is blocked)
    clamped_dofs = np.concatenate([3 * clamped + i for i in range(3)])

    u = fem.Function(V)
    v, du = ufl.TestFunction(V), ufl.TrialFunction(V)
    F = ufl.Identity(3) + ufl.grad(u)
    C = F.T * F
    I1 = ufl.tr(C)
    I2 = 0.5 * (I1 * I1 - ufl.tr(C * C))
    I3 = ufl.det(C)
    psi = C1 * (I1 - 3) + C2 * (I2 - 3) + A * (I3 - 1) - (C1 + 2 * C2 + A) * ufl.ln(I3)
    lam = fem.Constant(mesh, PETSc.ScalarType(0.0))
    b = ufl.as_vector((0.0, 0.0, -RHO * G))
    dx = ufl.dx(metadata={"quadrature_degree": 1})
    Pi = psi * dx - lam * ufl.dot(b, u) * dx
    R_form = fem.form(ufl.derivative(Pi, u, v))
    K_form = fem.form(ufl.derivative(ufl.derivative(Pi, u, v), u, du))
    f_form = fem.form(ufl.dot(b, v) * dx)

    K = fem.petsc.create_matrix(K_form)
    R = fem.petsc.create_vector(R_form)
    f = fem.petsc.assemble_vector(f_form)
    f.array[clamped_dofs] = 0.0
    f_norm = f.norm()
    dU = K.createVecRight()
    ksp = PETSc.KSP().create(mesh.comm)
    ksp.setType("preonly")
    ksp.getPC().setType("lu")
    ksp.getPC().setFactorSolverType("mumps")

    t_assembly = t_solve = 0.0
    newton = 0
    for k in range(1, INCREMENTS + 1):
        lam.value = k / INCREMENTS
        for it in range(31):
            t0 = time.perf_counter()
            K.zeroEntries()
            fem.petsc.assemble_matrix(K, K_form, bcs=[bc])
            K.assemble()
            with R.localForm() as r:
                r.set(0.0)
            fem.petsc.assemble_vector(R, R_form)
            t_assembly += time.perf_counter() - t0
            # TissueContact's test: |R| on the free DoFs below TOLERANCE
            # times the larger of the load's and the reactions' norms
            reaction = np.linalg.norm(R.array[clamped_dofs])
            fem.petsc.set_bc(R, [bc])
            scale = max(lam.value * f_norm, reaction)
            if R.norm() <= TOLERANCE * scale:
                break
            if it == 30:
                raise RuntimeError("FEniCSx: Newton did not converge")
            t0 = time.perf_counter()
            ksp.setOperators(K)
            ksp.solve(R, dU)
            t_solve += time.perf_counter() - t0
            u.vector.axpy(-1.0, dU)
            u.x.scatter_forward()
            newton += 1

    # the displacement at the tip vertex
    tree = geometry.BoundingBoxTree(mesh, 3)
    point = np.array([TIP])
    cells = geometry.compute_colliding_cells(
        mesh, geometry.compute_collisions(tree, point), point
    )
    tip = u.eval(point, [cells.links(0)[0]]).reshape(-1)
    return {
        "unknowns": V.dofmap.index_map.size_global * 3,
        "newton": newton,
        "assembly": t_assembly,
        "solve": t_solve,
        "tip": list(tip),
    }


def main():
    quick = "--quick" in sys.argv
    try:
        import dolfinx  # noqa: F401
        import gmsh  # noqa: F401
    except ImportError as e:
        print(f"peer_fenicsx: skipped ({e}); apt-get install python3-dolfinx python3-gmsh")
        return 0
    if not os.path.exists(DRIVER):
        print(f"peer_fenicsx: {DRIVER} is missing; cmake --build build --target performance")
        return 1

    sizes = [0.04] if quick else [0.04, 0.02, 0.01]
    print("Clamped Mooney-Rivlin beam under gravity, P1, 4 increments, MUMPS, one thread")
    header = (
        f"{'h':>6} {'tets':>7} {'unknowns':>8} {'tip uz (ours)':>22} {'rel. diff':>9} "
        f"{'Newton ours/FEniCSx':>19} {'assembly s ours/FEniCSx':>24} {'ratio':>6} "
        f"{'solve s ours/FEniCSx':>21} {'ratio':>6}"
    )
    print(header)
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for h in sizes:
            mesh = os.path.join(tmp, f"beam_{h}.msh")
            prm = os.path.join(tmp, f"beam_{h}.prm")
            n_tets = make_mesh(h, mesh)
            write_prm(mesh, prm, os.path.join(tmp, "out"))
            ours = run_ours(prm)
            peer = run_fenicsx(mesh)
            diff = max(abs(a - b) for a, b in zip(ours["tip"], peer["tip"])) / max(
                abs(c) for c in peer["tip"]
            )
            worst = max(worst, diff)
            print(
                f"{h:>6} {n_tets:>7} {ours['unknowns']:>8} {ours['tip'][2]:>22.15e} {diff:>9.1e} "
                f"{ours['newton']:>9} / {peer['newton']:<7} "
                f"{ours['assembly']:>11.3f} / {peer['assembly']:<10.3f} "
                f"{ours['assembly'] / peer['assembly']:>6.2f} "
                f"{ours['solve']:>9.3f} / {peer['solve']:<9.3f} "
                f"{ours['solve'] / peer['solve']:>6.2f}"
            )
    print(f"largest relative difference of the tip displacement: {worst:.1e} "
          f"({'within' if worst < 1e-10 else 'NOT within'} 1e-10)")
    return 0 if worst < 1e-10 else 1


if __name__ == "__main__":
    sys.exit(main())
