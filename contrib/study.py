#!/usr/bin/env python3
"""Run a study: one scene swept over prm entries, gathered into a CSV and a plot.

    contrib/study.py prm/studies/NAME.prm [--program build/tissue-contact]

A study file is a scene's parameter file with one extra subsection, which this
script removes before it runs the program:

    subsection Study
      # one line per swept entry: "path/to/Entry = value 1 | value 2 | ...";
      # "path/A & path/B = ..." sets both entries to each value
      set Sweep     = Discretization/Polynomial degree = 1 | 2; \\
                      Mesh/Box subdivisions = 8, 2, 2 | 16, 4, 4
      set Combine   = product          # or zip (the lists side by side)
      set Skip      = Discretization/Polynomial degree = 2 & \\
                      Bodies/Body 0/Volumetric term = nodal average
                                       # cases not to run: each item (items
                                       # separated by ";") skips the cases
                                       # with all of its "entry = value"
      set Quantity  = strain_energy    # a column of <base>-statistics.csv, last row
      set Reference = finest           # the last case's quantity, a number,
                                       # or none (no error column); "finest
                                       # per ENTRY": the last case with the
                                       # same value of that swept entry
      set Plot      = unknowns, error, loglog; wall_time, error, loglog
                                       # x, y, lin or loglog; one figure each
      set Curves    = Discretization/Polynomial degree
                                       # one curve per value (per combination
                                       # of values) of these swept entries;
                                       # default: the first swept entry
      set Key       = bottom left      # gnuplot's key position and layout
                                       # (top right; long titles fit
                                       # better with "Left reverse")
    end

Each case runs `tissue-contact case.prm` in its own folder under
study-output/NAME/ and is measured: wall time, unknowns, increments, Newton and
linear iterations (from the run summary), peak memory of the process (its
maximum resident set, from wait4), the quantity and its relative error against
the reference. Written: study-output/NAME/NAME.csv, and with gnuplot
NAME.png (NAME-2.png, ...) beside it, one curve per value of the first
swept entry (or of the Curves entries). Nothing here
is a test; the studies and their figures are described in doc/users/choosing.md.
"""
import csv
import itertools
import os
import re
import shutil
import subprocess
import sys
import time


def split_study(text):
    """The scene text without the Study subsection, and the Study entries."""
    lines, study, inside, depth = [], {}, False, 0
    joined = re.sub(r"\\\s*\n\s*", " ", text)  # continuation lines
    for line in joined.splitlines():
        stripped = line.split("#", 1)[0].strip()
        if not inside and stripped == "subsection Study":
            inside, depth = True, 1
            continue
        if inside:
            if stripped.startswith("subsection"):
                depth += 1
            elif stripped == "end":
                depth -= 1
                if depth == 0:
                    inside = False
                continue
            m = re.match(r"set\s+(\w+)\s*=\s*(.*)$", stripped)
            if m:
                study[m.group(1)] = m.group(2).strip()
            continue
        lines.append(line)
    return "\n".join(lines) + "\n", study


def sweep_cases(study):
    """[(entry path, [values])] and the list of cases: [{path: value}]."""
    entries = []
    for item in study["Sweep"].split(";"):
        path, values = item.split("=", 1)
        entries.append((path.strip(), [v.strip() for v in values.split("|")]))
    lists = [v for _, v in entries]
    if study.get("Combine", "product") == "zip":
        if len({len(v) for v in lists}) != 1:
            sys.exit("study: Combine = zip needs lists of equal length")
        combos = list(zip(*lists))
    else:
        combos = list(itertools.product(*lists))
    cases = [dict(zip([p for p, _ in entries], c)) for c in combos]
    skips = []
    for item in filter(None, (i.strip() for i in study.get("Skip", "").split(";"))):
        conditions = {}
        for condition in item.split("&"):
            path, value = condition.split("=", 1)
            conditions[path.strip()] = value.strip()
        skips.append(conditions)
    return entries, [
        case
        for case in cases
        if not any(all(case.get(p) == v for p, v in skip.items()) for skip in skips)
    ]


def with_entries(scene, case, folder):
    """The scene text with the case's entries and its output folder set (as
    subsections appended at the end, which override earlier values)."""
    text = scene
    expanded = [(p.strip(), v) for path, v in case.items()
                for p in path.split("&")]
    for path, value in expanded + [
        ("Output/Directory", folder),
        ("Output/Base name", "case"),
        ("Output/Write VTU", "false"),
        ("Output/Checkpoint every n steps", "0"),
        ("Output/Print timing", "false"),
    ]:
        parts = path.split("/")
        text += "".join(f"subsection {p}\n" for p in parts[:-1])
        text += f"  set {parts[-1]} = {value}\n" + "end\n" * (len(parts) - 1)
    return text


def run_case(program, prm_file, log_file):
    """Run the program; wall time, peak resident set (MiB), exit status."""
    start = time.perf_counter()
    with open(log_file, "w") as log:
        process = subprocess.Popen([program, prm_file], stdout=log,
                                   stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    return wall, usage.ru_maxrss / 1024.0, os.waitstatus_to_exitcode(status)


def summary(log_file):
    text = open(log_file).read()
    out = {}
    m = re.search(r"(\d+) unknowns", text)
    out["unknowns"] = int(m.group(1)) if m else None
    m = re.search(r"Converged: (\d+) increments \((\d+) cut back\), (\d+) "
                  r"Newton iterations, (\d+) linear iterations", text)
    if m:
        out.update(increments=int(m.group(1)), cutbacks=int(m.group(2)),
                   newton=int(m.group(3)), linear=int(m.group(4)))
    m = re.search(r"error: (.*)", text)
    out["failure"] = m.group(1)[:200] if m else ""
    return out


def last_value(statistics, column):
    with open(statistics) as f:
        rows = list(csv.DictReader(f))
    return float(rows[-1][column]) if rows and column in rows[-1] else None


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        print(__doc__)
        return 2
    study_file = args[0]
    program = "build/tissue-contact"
    if "--program" in args:
        program = args[args.index("--program") + 1]
    program = os.path.abspath(program)
    name = os.path.splitext(os.path.basename(study_file))[0]
    scene, study = split_study(open(study_file).read())
    for key in ("Sweep", "Quantity"):
        if key not in study:
            sys.exit(f"study: {study_file} lacks 'set {key}' in subsection Study")
    entries, cases = sweep_cases(study)
    root = os.path.abspath(os.path.join("study-output", name))
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    # relative paths in the scene (meshes) stay relative to the study file
    scene = re.sub(r"(set\s+File\s*=\s*)(\S+)",
                   lambda m: m.group(1) + os.path.abspath(os.path.join(
                       os.path.dirname(study_file), m.group(2))), scene)

    rows = []
    for i, case in enumerate(cases):
        folder = os.path.join(root, f"case{i:03d}")
        os.makedirs(folder)
        prm = os.path.join(folder, "case.prm")
        open(prm, "w").write(with_entries(scene, case, folder))
        wall, memory, status = run_case(program, prm,
                                        os.path.join(folder, "log.txt"))
        row = dict(case)
        row.update(summary(os.path.join(folder, "log.txt")))
        row.update(wall_time=round(wall, 3), peak_MiB=round(memory, 1),
                   status=status)
        stats = os.path.join(folder, "case-statistics.csv")
        row["quantity"] = (last_value(stats, study["Quantity"])
                           if status == 0 and os.path.exists(stats) else None)
        rows.append(row)
        print(f"case {i + 1}/{len(cases)}: "
              + ", ".join(f"{p} = {v}" for p, v in case.items())
              + f": {wall:.2f} s, {row['quantity']}"
              + (f" FAILED: {row['failure']}" if status else ""), flush=True)

    def swept(name):
        """The swept entry named by its path or by its last part."""
        for path, _ in entries:
            if name in (path, path.split("&")[0].strip().split("/")[-1]):
                return path
        sys.exit(f"study: '{name}' is no swept entry")

    reference = study.get("Reference", "finest")
    group = None
    m = re.match(r"finest per (.+)$", reference)
    if m:
        group = swept(m.group(1).strip())
    for row in rows:
        if reference == "none":
            ref_row, ref = None, None
        elif reference == "finest" or group:
            ref_row = [r for r in rows
                       if group is None or r[group] == row[group]][-1]
            ref = ref_row["quantity"]
        else:
            ref_row, ref = None, float(reference)
        q = row["quantity"]
        row["error"] = (abs(q - ref) / abs(ref)
                        if q is not None and ref not in (None, 0.0) else None)
        if row is ref_row:
            row["error"] = None  # the reference itself
    table = os.path.join(root, name + ".csv")
    columns = list(cases[0].keys()) + [
        "unknowns", "increments", "cutbacks", "newton", "linear", "wall_time",
        "peak_MiB", "quantity", "error", "status", "failure"]
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    print(f"table: {table} (quantity: {study['Quantity']}, reference: "
          f"{reference}"
          + (f" = {rows[-1]['quantity']}" if reference == "finest" else "")
          + ")")

    if "Plot" in study and shutil.which("gnuplot"):
        by = [swept(c.strip()) for c in study.get(
            "Curves", entries[0][0]).split(",")]
        curves = list(dict.fromkeys(tuple(row[b] for b in by) for row in rows))

        def column(name):
            """A column by its name, or a swept entry by its last part."""
            keys = dict.fromkeys(k for row in rows for k in row)
            for key in keys:
                if key == name or key.split("&")[0].strip().split("/")[-1] \
                        == name:
                    return key
            sys.exit(f"study: Plot names '{name}', which is no column")

        for k, plot in enumerate(study["Plot"].split(";")):
            x, y, *scale = [s.strip() for s in plot.split(",")]
            x, y = column(x), column(y)
            stem = os.path.join(root, name + ("" if k == 0 else f"-{k + 1}"))
            with open(stem + ".dat", "w") as f:
                for values in curves:
                    f.write('"' + ", ".join(
                        f'{b.split("&")[0].strip().split("/")[-1]} = {v}'
                        for b, v in zip(by, values)) + '"\n')
                    for row in rows:
                        if tuple(row[b] for b in by) == values \
                                and row.get(x) is not None \
                                and row.get(y) is not None:
                            f.write(f"{row[x]} {row[y]}\n")
                    f.write("\n\n")
            script = (f"set terminal pngcairo size 800,560 noenhanced\n"
                      f"set output '{stem}.png'\n"
                      f"set xlabel '{x.split('&')[0].strip()}'\n"
                      f"set ylabel '{y}'\n"
                      f"set key {study.get('Key', 'top right')} "
                      f"font ',9' samplen 2\n"
                      f"set grid\n"
                      + ("set logscale xy\n" if scale and scale[0] == "loglog"
                         else "")
                      + f"set title '{name}: {y} of {study['Quantity']}'\n"
                      + "plot " + ", ".join(
                          f"'{stem}.dat' index {i} using 1:2 with linespoints "
                          f"title columnheader(1)"
                          for i in range(len(curves))) + "\n")
            subprocess.run(["gnuplot"], input=script, text=True, check=True)
            print(f"figure: {stem}.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
