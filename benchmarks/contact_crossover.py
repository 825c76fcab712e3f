"""Where the sparse contact solve starts to pay (the cost model of Stepper::sparse_contact_pays,
issue 54): one substep of the same scene as contact_scaling.py with each contact solve forced,
on the paper's rectangle (nx = ny = 20 ... 160) and on the pad refined to 101 ... 401 contact
nodes. The condensed solve's dense work grows as (2 n_c)^2, a sparse solve's with the unknowns
n_f; the measured crossover in r = (2 n_c)^2 / n_f is kappa, the constant in stepper.hpp
(python_tests/test_docs.py checks it against this file).

Writes benchmarks/results/contact_crossover.json and contact_crossover.md.

    .venv/bin/python benchmarks/contact_crossover.py [--build DIR]
"""
import argparse
import json
import math
import pathlib
import tempfile

import contact_scaling

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        bodies = [(f"rectangle nx = {nx}", f"rect:{nx}") for nx in (20, 40, 80, 160)]
        bodies += [(f"pad, {n} requested", contact_scaling.pad_mesh(tmp, n))
                   for n in (101, 201, 251, 301, 351, 401)]
        for name, mesh in bodies:
            times = {}
            for path in ("condensed", "sparse"):
                r = contact_scaling.measure(args.build, mesh, 0, path)
                times[path] = r["substep_seconds"]
            ratio = (2 * r["contact_nodes"]) ** 2 / r["unknowns"]
            row = {"body": name, "contact_nodes": r["contact_nodes"], "unknowns": r["unknowns"],
                   "ratio": ratio, "condensed_seconds": times["condensed"],
                   "sparse_seconds": times["sparse"]}
            print(json.dumps(row), flush=True)
            rows.append(row)
    condensed_wins = [r["ratio"] for r in rows if r["condensed_seconds"] <= r["sparse_seconds"]]
    sparse_wins = [r["ratio"] for r in rows if r["sparse_seconds"] < r["condensed_seconds"]]
    below, above = max(condensed_wins), min(sparse_wins)
    kappa = math.sqrt(below * above) if below < above else None
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "contact_crossover.json").write_text(json.dumps(
        {"rows": rows, "condensed_wins_up_to": below, "sparse_wins_from": above,
         "kappa": kappa}, indent=1))
    lines = ["# Where the sparse contact solve starts to pay", "",
             "`.venv/bin/python benchmarks/contact_crossover.py`: one substep of "
             "contact_scaling.py's scene with each contact solve forced; r = (2 n_c)² / n_f.", "",
             "| body | contact nodes | unknowns | r | condensed [ms] | sparse [ms] |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['body']} | {r['contact_nodes']} | {r['unknowns']} | {r['ratio']:.1f} | "
                     f"{1e3 * r['condensed_seconds']:.3g} | {1e3 * r['sparse_seconds']:.3g} |")
    lines += ["", f"The condensed solve is faster up to r = {below:.1f}, the sparse one from "
              f"r = {above:.1f}: kappa = {kappa:.0f} (their geometric mean)." if kappa else
              "The two overlap: no single crossover."]
    (OUT / "contact_crossover.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
