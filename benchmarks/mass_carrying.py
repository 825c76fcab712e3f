"""Massless against mass-carrying reduction (build/bench_mass_carrying): the massless-boundary
reduced body and standard Craig-Bampton with the same modes, beside the full body, on an
impact and on damped sliding, at nx = 20, 40, 80, each mesh's usual step (4e-6 s x 20 / nx)
and 4x and 16x it. Per run: cost (wall seconds per simulated second, all in one run), the
energy balance's largest residual, the errors of normal force and energy (L2 over the
outputs, relative to the full body at its step), and the normal force's oscillation: its
total variation and its peak against the full body's. The step each allows: the largest whose
errors stay within 5 %.

    .venv/bin/python benchmarks/mass_carrying.py [--meshes 20,40,80] [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import subprocess

import numpy as np

from reduced_body_fmu import l2

ROOT = pathlib.Path(__file__).resolve().parents[1]
MODES, FACTORS, ALLOWED = (40, 160), (1, 4, 16), 0.05
INTERVAL = {"impact": 1e-5, "sliding": 1e-4}  # the scenes' output steps: a substep is at most one


def measure(nx, modes):
    dt = 4e-6 * 20 / nx
    out = subprocess.run([str(ROOT / "build" / "bench_mass_carrying"), str(nx), repr(dt),
                          str(modes), ",".join(map(str, FACTORS))],
                         check=True, capture_output=True, text=True).stdout
    data = json.loads(out)
    rows, seen = [], set()
    full = {r["scene"]: r for r in data["runs"] if r["body"] == "full"}
    for r in data["runs"]:
        # The substep taken: at most the output step (a larger internal_step gives the same run).
        r["dt"] = min(r["dt"], INTERVAL[r["scene"]])
        if (r["scene"], r["body"], r["dt"]) in seen:
            continue
        seen.add((r["scene"], r["body"], r["dt"]))
        ref = full[r["scene"]]
        n, e = np.array(r["normal_force"]), np.array(r["energy"])
        n_ref, e_ref = np.array(ref["normal_force"]), np.array(ref["energy"])
        row = {k: r[k] for k in ("scene", "body", "modes", "dt", "setup_s",
                                 "wall_per_simulated_s", "balance", "failure")}
        row["nx"] = nx
        complete = not r["failure"] and len(n) == len(n_ref)
        row["error_normal_force"] = l2(n, n_ref) if complete else None
        row["error_energy"] = l2(e, e_ref) if complete else None
        row["variation_ratio"] = (float(np.abs(np.diff(n)).sum() / np.abs(np.diff(n_ref)).sum())
                                  if complete else None)
        row["peak_ratio"] = float(n.max() / n_ref.max()) if complete else None
        rows.append(row)
    return rows


def allowed_steps(rows):
    """Per mesh, scene and reduced body: the largest step whose errors stay within ALLOWED."""
    best = {}
    for r in rows:
        if r["body"] == "full":
            continue
        key = (r["nx"], r["modes"], r["scene"], r["body"])
        ok = r["error_normal_force"] is not None and max(r["error_normal_force"],
                                                         r["error_energy"]) <= ALLOWED
        if ok and r["dt"] > best.get(key, 0):
            best[key] = r["dt"]
        best.setdefault(key, 0)
    return best


def table(rows):
    fmt = lambda x, f: "—" if x is None else format(x, f)  # noqa: E731
    lines = ["Massless against mass-carrying reduction, each with the same modes, beside the "
             "full body (`benchmarks/mass_carrying.py`, one run; errors "
             "L2 over the outputs relative to the full body at the mesh's usual step; "
             "variation and peak: the normal force's total variation and maximum over the full "
             "body's; balance: the largest |E - E(0) - works| over the largest energy):", "",
             "| nx | scene | body | modes | dt [s] | cost [s/s] | normal force error | "
             "energy error | variation | peak | balance | set-up [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['nx']} | {r['scene']} | {r['body']} | {r['modes'] or '—'} | {r['dt']:.3g} | "
            f"{r['wall_per_simulated_s']:.3g} | {fmt(r['error_normal_force'], '.2e')} | "
            f"{fmt(r['error_energy'], '.2e')} | {fmt(r['variation_ratio'], '.3g')} | "
            f"{fmt(r['peak_ratio'], '.3g')} | {r['balance']:.1e} | {r['setup_s']:.2f} |"
            + (f" failed: {r['failure'][:60]}" if r["failure"] else ""))
    lines += ["", f"The largest step within {ALLOWED:.0%} (of those tried; 0: none):", "",
              "| nx | modes | scene | massless | Craig–Bampton |", "|---|---|---|---|---|"]
    best = allowed_steps(rows)
    for nx, modes, scene in sorted({k[:3] for k in best}):
        lines.append(f"| {nx} | {modes} | {scene} | {best[(nx, modes, scene, 'massless')]:.3g} | "
                     f"{best[(nx, modes, scene, 'craig_bampton')]:.3g} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default="20,40,80")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    rows = []
    for nx in map(int, args.meshes.split(",")):
        for modes in MODES:
            # The full body once per mesh: its rows from the first mode count only.
            rows += [r for r in measure(nx, modes) if r["body"] != "full" or modes == MODES[0]]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "mass_carrying.json").write_text(json.dumps(rows, indent=1))
    (args.out / "mass_carrying.md").write_text(table(rows))
    print(table(rows))


if __name__ == "__main__":
    main()
