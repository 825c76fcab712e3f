"""Where the sparse contact solve starts to pay (the cost model of Stepper::sparse_contact_pays,
issue 54): one substep of the same scene as contact_scaling.py with each contact solve forced,
on the paper's rectangle (nx = ny = 20, 80) and on the pad refined to 101 ... 801 contact
nodes, at friction coefficients F = 0, 0.3, 1.2 and 3. The condensed solve's dense work grows
as (2 n_c)^2, a sparse solve's with the unknowns n_f, and the sparse solve's friction costs
held solves in proportion to F; the model takes the sparse solve where
r = (2 n_c)^2 / n_f > kappa(F) = kappa_0 + kappa_F F. Rows where one solve is faster by more
than MARGIN bound kappa(F) (the others are this machine's noise);
python_tests/test_docs.py checks stepper.hpp's constants against them.

Writes benchmarks/results/contact_crossover.json and contact_crossover.md.

    .venv/bin/python benchmarks/contact_crossover.py [--build DIR] [--analyze-only]
"""
import argparse
import json
import math
import pathlib
import tempfile

import contact_scaling

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
FRICTIONS = (0.0, 0.3, 1.2, 3.0)
MARGIN = 1.5


def measure_rows(build):
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        bodies = [(f"rectangle nx = {nx}", f"rect:{nx}") for nx in (20, 80)]
        bodies += [(f"pad, {n} requested", contact_scaling.pad_mesh(tmp, n))
                   for n in (101, 201, 251, 301, 401, 801)]
        for friction in FRICTIONS:
            for name, mesh in bodies:
                times = {}
                for path in ("condensed", "sparse"):
                    r = contact_scaling.measure(build, mesh, 0, path, friction=friction)
                    times[path] = r["substep_seconds"]
                ratio = (2 * r["contact_nodes"]) ** 2 / r["unknowns"]
                row = {"body": name, "friction": friction, "contact_nodes": r["contact_nodes"],
                       "unknowns": r["unknowns"], "ratio": ratio,
                       "condensed_seconds": times["condensed"], "sparse_seconds": times["sparse"]}
                print(json.dumps(row), flush=True)
                rows.append(row)
    return rows


def faster(row):
    """"sparse" or "condensed" where one is faster by more than MARGIN, else None."""
    c, s = row["condensed_seconds"], row["sparse_seconds"]
    return "sparse" if c > MARGIN * s else "condensed" if s > MARGIN * c else None


def bounds(rows):
    """Per F: kappa(F) lies above every r where the condensed solve was clearly faster and
    below every r where the sparse one was."""
    out = {}
    for friction in FRICTIONS:
        mine = [r for r in rows if r["friction"] == friction]
        out[str(friction)] = {
            "above": max([r["ratio"] for r in mine if faster(r) == "condensed"], default=0),
            "below": min([r["ratio"] for r in mine if faster(r) == "sparse"], default=None)}
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--analyze-only", action="store_true",
                        help="the rows of the last results file, analyzed again")
    args = parser.parse_args()
    results = OUT / "contact_crossover.json"
    rows = (json.loads(results.read_text())["rows"] if args.analyze_only
            else measure_rows(args.build))
    kappa = bounds(rows)
    OUT.mkdir(parents=True, exist_ok=True)
    results.write_text(json.dumps({"margin": MARGIN, "rows": rows, "kappa_bounds": kappa}, indent=1))
    lines = ["# Where the sparse contact solve starts to pay", "",
             "`.venv/bin/python benchmarks/contact_crossover.py`: one substep of "
             "contact_scaling.py's scene with each contact solve forced, at several friction "
             f"coefficients F; r = (2 n_c)² / n_f; *faster* where by more than {MARGIN}×.", "",
             "| F | body | contact nodes | unknowns | r | condensed [ms] | sparse [ms] | faster |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['friction']} | {r['body']} | {r['contact_nodes']} | {r['unknowns']} | "
                     f"{r['ratio']:.1f} | {1e3 * r['condensed_seconds']:.3g} | "
                     f"{1e3 * r['sparse_seconds']:.3g} | {faster(r) or ''} |")
    lines += ["", "| F | κ(F) above | κ(F) below |", "|---|---|---|"]
    for friction, b in kappa.items():
        below = "—" if b["below"] is None else f"{b['below']:.1f}"
        lines.append(f"| {friction} | {b['above']:.1f} | {below} |")
    (OUT / "contact_crossover.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
