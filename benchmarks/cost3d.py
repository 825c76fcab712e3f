"""What a 3D body costs (issue 55): hemispheres of tetrahedra (benchmarks/hertz3d.py's shape) of
2.7k, 12.6k and 111k nodes, damped (beta = 4e-6 s), 1e-6 s substeps, the foundation at 20 m/s
along x, solved as the FMU would (the cost model's contact solve, the factor kernel's rule).
Three scenes per mesh:

* pressed: F = 0, the static start under a clamp displacement of -0.2 mm (Hertz's load), then
  held (the sparse contact solve);
* sliding: the same with F = 0.3 (isotropic friction). Not on the 111k-node mesh: its static
  start with friction takes ten load increments on a body whose factorization takes 20 minutes
  there (not measured);
* lifted: F = 0, the same body 1 mm above the foundation (no contact: the floor).

For each: the set-up (discretization, factors and the static start), one substep (mean over 30
after the first step), one solve with the run's own last factor (the floor), that factor's
kernel, flops and nonzeros, and the peak memory. Runs build/bench_contact_scaling, one process
per case.

Writes benchmarks/results/cost3d.json and cost3d.md.

    .venv/bin/python benchmarks/cost3d.py [--build build] [--meshes 0,1] [--scenes pressed,lifted]

By default the two smaller meshes; --meshes 2 the 111k-node one (17 GB: run it alone; its
lifted scene takes 35 minutes, its pressed one 62). --meshes and --scenes run those only
(indices into MESHES, names of SCENES) and keep the other rows of the results file, which is
written after each case.
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
# Contact and far element sizes, and whether the sliding scene runs.
MESHES = [(5e-4, 1e-2, True), (2.5e-4, 1e-2, True), (1.25e-4, 3e-3, False)]
SCENES = {"pressed": ["0", "3", "-2e-4", "0"], "sliding": ["0.3", "3", "-2e-4", "0"],
          "lifted": ["0", "3", "-2e-4", "1e-3"]}  # F, dimension, top, gap


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--meshes", default="0,1",
                        help="which meshes (indices into MESHES, smallest first; 2, the 111k-node "
                             "one, takes 1.6 hours and 17 GB)")
    parser.add_argument("--scenes", default=",".join(SCENES), help="which scenes")
    parser.add_argument("--out", default=str(OUT), help="the results folder")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    program = pathlib.Path(args.build) / "bench_contact_scaling"
    chosen = [int(i) for i in args.meshes.split(",")]
    sizes = [m[0] for m in MESHES]
    results = out / "cost3d.json"
    scenes = args.scenes.split(",")
    rows = [r for r in json.loads(results.read_text())["rows"]
            if r["contact_size"] in sizes and not (sizes.index(r["contact_size"]) in chosen and r["scene"] in scenes)
            ] if results.exists() else []
    with tempfile.TemporaryDirectory() as tmp:
        for contact, far, sliding in (MESHES[i] for i in chosen):
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{contact:.3g}.msh", radius=0.05,
                                     contact_size=contact, far_size=far, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            nodes = int(path.read_text().split("$Nodes\n")[1].split()[1])
            for scene, extra in SCENES.items():
                if scene not in scenes or (scene == "sliding" and not sliding):
                    continue
                case = subprocess.run([str(program), str(path), "0", "automatic", "30", *extra],
                                      check=True, capture_output=True, text=True).stdout
                row = {"nodes": nodes, "scene": scene, "contact_size": contact, **json.loads(case)}
                rows.append(row)
                print(json.dumps(row), flush=True)
                write(rows, out)


def write(rows, out=OUT):
    """The results file and its table, rows in the order of MESHES and SCENES."""
    sizes, scenes = [m[0] for m in MESHES], list(SCENES)
    rows.sort(key=lambda r: (sizes.index(r["contact_size"]), scenes.index(r["scene"])))
    out.mkdir(parents=True, exist_ok=True)
    (out / "cost3d.json").write_text(json.dumps({"rows": rows}, indent=1) + "\n")
    lines = ["# What a 3D body costs", "",
             "`.venv/bin/python benchmarks/cost3d.py`: tetrahedral hemispheres (R = 50 mm), "
             "beta = 4e-6 s, 1e-6 s substeps, the foundation at 20 m/s; pressed: F = 0, static start "
             "under -0.2 mm, then held; sliding: the same with F = 0.3; lifted: F = 0, 1 mm above the "
             "foundation (no sliding scene on the largest: its static start with friction is ten load "
             "increments, not measured there). One process per case. The set-up is the simulation's construction (the "
             "discretization and the static start, whose load path has a factor of its own); the body's "
             "own factor is made in the first step, which is not timed. *One solve* is with the run's own last factor (the sparse "
             "contact solve's, its held dofs the identity's), whose kernel, analysis flops and "
             "nonzeros the table gives. *Static start*: of the set-up, the load path's own body (its "
             "discretization), the load paths (their factor and contact solves), and their held solves and "
             "refactorizations (— in rows measured before the bench reported them).", "",
             "| nodes | unknowns | contact nodes | scene | contact solve | set-up incl. static start [s] | static start: its body s, its paths s, held solves, refactorizations | substep [ms] | one solve [ms] | substep / solve | factor | factor flops | factor nonzeros | peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    def factor(r):  # rows measured before the bench reported its factor have none
        return (f"{r['factor_kernel']} | {r['factor_flops']:.2g} | {r['factor_nonzeros']:.2g}"
                if "factor_kernel" in r else "— | — | —")
    def start(r):  # likewise
        return (f"{r['static_start_body_seconds']:.3g}, {r['static_start_path_seconds']:.3g}, "
                f"{r['static_start_held_solves']}, {r['static_start_refactorizations']}"
                if "static_start_path_seconds" in r else "—")
    for r in rows:
        lines.append(f"| {r['nodes']} | {r['unknowns']} | {r['contact_nodes']} | {r['scene']} | "
                     f"{'sparse' if r['sparse'] else 'condensed'} | "
                     f"{r['static_start_seconds']:.3g} | {start(r)} | {1e3 * r['substep_seconds']:.3g} | "
                     f"{1e3 * r['sparse_solve_seconds']:.3g} | {r['substep_per_solve']:.2f} | {factor(r)} | "
                     f"{r['peak_memory_mb']:.0f} |")
    (out / "cost3d.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
