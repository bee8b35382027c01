#!/usr/bin/python3
"""How far a contact scene's Newton path spreads (benchmark, not a test).

A scene with much contact does not follow one Newton path: a change that
moves the rounding (another linear solver's bits, another order of a sum)
can send a run of the knee 20 % more or fewer Newton iterations, so one
run before and one after a change that alters the path cannot tell whether
it helped (doc/theory/04-solver.md sec. 4.3). This script runs variants of
one scene that change nothing but the path: the Newton tolerance (times 1,
0.5 or 0.7) and the quasi-viscosity's factor (times 0.7 to 1.3), neither
of which changes the solution beyond the tolerance. It prints each run's
increments, cut-backs, Newton and linear iterations, shifted solves, run
time and linear-solve time, and over the runs their mean, standard
deviation, the mean's standard error and the median. Weigh a
path-changing rule by these, not by one run; on the coarse knee eight
variants tell apart only rules some 10 % apart (doc/theory/04-solver.md
sec. 4.5.1), so use more where the difference is smaller:

    cmake --build build --target tissue-contact
    /usr/bin/python3 tests/performance/path_spread.py [--quick] [--runs N]
        [--jobs J] [--program PATH] [scene.prm]

The scene is prm/knee_flexion.prm by default; --quick meshes the knee
coarsely, as the test scene/knee_flexion and `knee --quick` do (about 40 s
per run on one thread). Each run gets one thread, J runs (default 2) at a
time; --runs N (default 8, at most 24) variants; --program another build's
tissue-contact. VTU files and checkpoints are off, the output goes to a
temporary folder. Other settings (an environment variable a temporary
build reads, say) pass through the environment.
"""

import os
import re
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# the variants' factors on (Residual tolerance, Viscosity factor); the
# first twelve are those of the figures recorded before 2026-12-06 (in
# this order), the next twelve widen the sample
FACTORS = [(1.0, 1.0), (0.5, 1.0), (1.0, 1.2), (0.5, 1.2),
           (1.0, 0.8), (0.5, 0.8), (1.0, 1.1), (0.5, 1.1),
           (0.7, 1.0), (0.7, 1.2), (0.7, 0.8), (0.7, 1.1),
           (1.0, 0.9), (0.5, 0.9), (0.7, 0.9), (1.0, 1.3),
           (0.5, 1.3), (0.7, 1.3), (1.0, 0.7), (0.5, 0.7),
           (0.7, 0.7), (1.0, 1.05), (0.5, 1.05), (0.7, 1.05)]
# the program's defaults (solvers/newton_solver.h) where a file sets none
DEFAULTS = {"Residual tolerance": 1e-8, "Viscosity factor": 0.1}
COARSE_KNEE = "-setnumber h 0.06 -setnumber n_2pi 5 -setnumber pat_refine 2"


def newton_value(text, name):
    """The value the file sets in its subsection Newton, else the default."""
    section = re.search(r"subsection\s+Newton\b(.*?)\n\s*end\b", text, re.S)
    if section:
        m = re.search(r"set\s+" + name + r"\s*=\s*([0-9.eE+-]+)",
                      section.group(1))
        if m:
            return float(m.group(1))
    return DEFAULTS[name]


def run(program, text, index, factors, work):
    tol = factors[0] * newton_value(text, "Residual tolerance")
    visc = factors[1] * newton_value(text, "Viscosity factor")
    out = os.path.join(work, "run%d" % index)
    os.makedirs(out, exist_ok=True)
    prm = os.path.join(work, "run%d.prm" % index)
    with open(prm, "w") as f:
        f.write(text)
        f.write("\nsubsection Newton\n  set Residual tolerance = %.6g\n"
                "  set Viscosity factor = %.6g\nend\n" % (tol, visc))
        f.write("\nsubsection Output\n  set Directory = %s\n"
                "  set Write VTU = false\n  set Checkpoint every n steps = 0\n"
                "end\n" % out)
    env = dict(os.environ, DEAL_II_NUM_THREADS="1")
    p = subprocess.run([program, prm], cwd=work, env=env,
                       capture_output=True, text=True)
    log = p.stdout + p.stderr
    row = {"run": index, "tol": tol, "visc": visc}
    m = re.search(r"Converged: (\d+) increments \((\d+) cut back\), (\d+) "
                  r"Newton iterations, (\d+) linear iterations(?: \((\d+) "
                  r"solves with a shifted tangent\))?", log)
    if p.returncode != 0 or not m:
        last = [l for l in log.splitlines() if l.strip()][-1:] or ["no output"]
        row["failed"] = last[0][:100]
        return row
    row.update(increments=int(m.group(1)), cut=int(m.group(2)),
               newton=int(m.group(3)), linear=int(m.group(4)),
               shifted=int(m.group(5) or 0))

    def seconds(label):
        # deal.II's timer table: the first time on the label's line
        t = re.search(r"\|\s*" + label + r"\s*\|[^\n]*?([0-9.]+)s\s*\|",
                      log)
        return float(t.group(1)) if t else float("nan")
    row["run_s"] = seconds("Total wallclock time elapsed since start")
    row["solve_s"] = seconds("linear solve")
    return row


def main():
    args = sys.argv[1:]
    quick = "--quick" in args
    runs, jobs = 8, 2
    program = os.path.join(ROOT, "build", "tissue-contact")
    scene = os.path.join(ROOT, "prm", "knee_flexion.prm")
    i = 0
    while i < len(args):
        a = args[i]
        if a in ("--runs", "--jobs", "--program") and i + 1 < len(args):
            v = args[i + 1]
            i += 1
            if a == "--runs":
                runs = min(int(v), len(FACTORS))
            elif a == "--jobs":
                jobs = max(1, int(v))
            else:
                program = os.path.abspath(v)
        elif a != "--quick":
            scene = os.path.abspath(a)
        i += 1
    if not os.access(program, os.X_OK):
        sys.exit("no program at %s: build it first (cmake --build build "
                 "--target tissue-contact) or name one with --program" %
                 program)
    with open(scene) as f:
        text = f.read()
    # the variants are written elsewhere: files named relative to the
    # scene's folder get its path
    folder = os.path.dirname(scene)
    text = re.sub(r"(set\s+File\s*=\s*)(\S.*)",
                  lambda m: m.group(1) + (m.group(2) if os.path.isabs(
                      m.group(2)) else os.path.join(folder, m.group(2))),
                  text)
    if quick:
        if "knee.geo" not in text:
            sys.exit("--quick knows the coarse mesh of meshes/knee.geo only")
        text += "\nsubsection Mesh\n  set Gmsh options = %s\nend\n" % COARSE_KNEE
    with tempfile.TemporaryDirectory() as work, \
            ThreadPoolExecutor(max_workers=jobs) as pool:
        rows = list(pool.map(
            lambda k: run(program, text, k + 1,
                          FACTORS[k], work), range(runs)))

    print("Newton paths of %s%s: %d variants, one thread each, %d at a time"
          % (os.path.relpath(scene, ROOT), " (--quick)" if quick else "", runs,
             jobs))
    print()
    head = ("run", "tolerance", "viscosity", "incr", "cut", "Newton",
            "linear", "shifted", "run s", "solve s")
    print(("%-5s %-10s %-10s %-6s %-5s %-8s %-8s %-8s %-8s %-8s") % head)
    good = [r for r in rows if "failed" not in r]
    for r in rows:
        if "failed" in r:
            print("%-5d %-10.3g %-10.3g failed: %s" % (r["run"], r["tol"],
                                                       r["visc"], r["failed"]))
        else:
            print("%-5d %-10.3g %-10.3g %-6d %-5d %-8d %-8d %-8d %-8.1f %-8.1f"
                  % (r["run"], r["tol"], r["visc"], r["increments"], r["cut"],
                     r["newton"], r["linear"], r["shifted"], r["run_s"],
                     r["solve_s"]))
    if len(good) >= 2:
        print()
        print("%-22s %-10s %-10s %-10s %-10s" % ("over the runs", "mean",
                                                "sd", "se", "median"))
        for key, label in (("newton", "Newton iterations"),
                           ("linear", "linear iterations"),
                           ("cut", "cut-backs"),
                           ("run_s", "run (s)")):
            values = [r[key] for r in good]
            sd = statistics.stdev(values)
            print("%-22s %-10.1f %-10.1f %-10.1f %-10.1f" % (
                label, statistics.mean(values), sd, sd / len(values) ** 0.5,
                statistics.median(values)))
        print()
        print("se: the standard error of the mean, sd / sqrt(runs). Two "
              "rules' means\ndiffer beyond the paths' spread only where "
              "they are more than about\ntwice sqrt(se1^2 + se2^2) apart.")
    return 0 if len(good) == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
