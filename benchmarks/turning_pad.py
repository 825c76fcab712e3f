"""What the turning pad of examples/turning_pad_3d.py costs (issue 71): the pad (contactbody.meshes.pad3d,
60 x 20 x 40 mm) at 4 mm and 2 mm cells, F = 0.5, damping_stiffness 2e-6 s, 4e-6 s substeps,
pressed by 0.1 mm from the static start, the foundation at 0.2 m/s along x, its heading turning a
right angle from 0.2 to 1.2 ms, then along z to 3 ms (build/bench_turning_pad, one process per
case, in one run). Three cases per mesh:

* full: the FMU's contact solve (automatic: slipping rows held in the factor where their rho
  allows, GCR on the rest);
* full, slips by GCR: the contact path sparse_gcr, every slip law left to GCR (the solve before
  the slipping rows went into the factor);
* reduced: modes = 40, the massless edge.

For each phase (straight, turning, along z): held solves a substep (exact counts), Newton
iterations a substep, refactorizations, CPU ms a substep; for the run the set-up, CPU seconds
per simulated millisecond, and the final normal force and friction (the same solution).

Writes benchmarks/results/turning_pad.json and turning_pad.md.

    .venv/bin/python benchmarks/turning_pad.py [--build build] [--sizes 4e-3,2e-3]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
CASES = {"full": ("0", "automatic"), "full, slips by GCR": ("0", "sparse_gcr"), "reduced, 40 modes": ("40", "automatic")}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--sizes", default="4e-3,2e-3", help="cell sizes [m]")
    parser.add_argument("--out", default=str(OUT))
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_turning_pad"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for size in (float(s) for s in args.sizes.split(",")):
            path = meshes.pad3d(pathlib.Path(tmp) / f"pad_{size:.3g}.msh", size=size)
            for case, (modes, contact_path) in CASES.items():
                run = json.loads(subprocess.run([str(program), str(path), modes, contact_path], check=True,
                                                capture_output=True, text=True).stdout)
                row = {"size_mm": 1e3 * size, "case": case, **run}
                rows.append(row)
                print(json.dumps(row), flush=True)
    for r in rows:
        full = next(f for f in rows if f["size_mm"] == r["size_mm"] and f["case"] == "full")
        r["over_full"] = r["cpu_seconds_per_simulated_ms"] / full["cpu_seconds_per_simulated_ms"]
        r["normal_force_difference"] = abs(r["normal_force"] - full["normal_force"]) / abs(full["normal_force"])
    write(rows, pathlib.Path(args.out))


def write(rows, out):
    out.mkdir(parents=True, exist_ok=True)
    (out / "turning_pad.json").write_text(json.dumps({"rows": rows}, indent=1) + "\n")
    lines = ["# The turning pad: what 3D sliding costs while the slip direction turns", "",
             "`.venv/bin/python benchmarks/turning_pad.py`: the pad of `examples/turning_pad_3d.py` "
             "(F = 0.5, damping_stiffness 2e-6 s, 4e-6 s substeps, static start under -0.1 mm, the "
             "foundation at 0.2 m/s, its heading turning from x to z between 0.2 and 1.2 ms, 3 ms in "
             "all). *full*: the FMU's contact solve; *slips by GCR*: the contact path `sparse_gcr`; "
             "*reduced*: 40 modes. Per phase: held solves and Newton iterations a substep (exact "
             "counts), refactorizations, CPU ms a substep (one process each, in one run).", "",
             "| cells [mm] | nodes | contact nodes | case | set-up [s] | straight: solves, Newton, refactorizations, ms | turning | along z | CPU s per simulated ms | over full | normal force difference |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        phases = [f"{p['held_solves_per_substep']:.2f}, {p['newton_iterations_per_substep']:.2f}, "
                  f"{p['refactorizations']}, {p['cpu_ms_per_substep']:.3g}" for p in r["phases"]]
        lines.append(f"| {r['size_mm']:.3g} | {r['nodes']} | {r['contact_nodes']} | {r['case']} | "
                     f"{r['setup_seconds']:.3g} | {' | '.join(phases)} | "
                     f"{r['cpu_seconds_per_simulated_ms']:.3g} | {r['over_full']:.2f} | "
                     f"{r['normal_force_difference']:.1e} |")
    (out / "turning_pad.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
