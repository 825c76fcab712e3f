"""What a 3D body costs (issue 55): hemispheres of tetrahedra (benchmarks/hertz3d.py's shape) of
2.7k and 12.6k nodes (26k and 53k with --largest 3 and 4), damped (beta = 4e-6 s), 1e-6 s
substeps, the foundation at 20 m/s along x, solved as the FMU would (the cost model's contact
solve, the factor kernel's rule). Three scenes per mesh:

* pressed: F = 0, the static start under a clamp displacement of -0.2 mm (Hertz's load), then
  held (the sparse contact solve);
* sliding: the same with F = 0.3 (isotropic friction: the condensed contact solve);
* lifted: F = 0, the same body 1 mm above the foundation (no contact: the floor).

For each: the set-up (discretization, factors and the static start), one substep (mean over 30
after the first step), one solve with K's factor beside it, and the peak memory. Runs
build/bench_contact_scaling, one process per case.

Writes benchmarks/results/cost3d.json and cost3d.md.

    .venv/bin/python benchmarks/cost3d.py [--build build] [--largest N]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
MESHES = [(5e-4, 1e-2), (2.5e-4, 1e-2), (2e-4, 6e-3), (1.6e-4, 4e-3)]  # contact, far element sizes
SCENES = {"pressed": ["0", "3", "-2e-4", "0"], "sliding": ["0.3", "3", "-2e-4", "0"],
          "lifted": ["0", "3", "-2e-4", "1e-3"]}  # F, dimension, top, gap


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--largest", type=int, default=2, help="how many meshes, smallest first")
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_contact_scaling"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for contact, far in MESHES[:args.largest]:
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{contact:.3g}.msh", radius=0.05,
                                     contact_size=contact, far_size=far, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            nodes = int(path.read_text().split("$Nodes\n")[1].split()[1])
            for scene, extra in SCENES.items():
                out = subprocess.run([str(program), str(path), "0", "automatic", "30", *extra],
                                     check=True, capture_output=True, text=True).stdout
                row = {"nodes": nodes, "scene": scene, "contact_size": contact, **json.loads(out)}
                rows.append(row)
                print(json.dumps(row))
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "cost3d.json").write_text(json.dumps({"rows": rows}, indent=1) + "\n")
    lines = ["# What a 3D body costs", "",
             "`.venv/bin/python benchmarks/cost3d.py`: tetrahedral hemispheres (R = 50 mm), "
             "beta = 4e-6 s, 1e-6 s substeps, the foundation at 20 m/s; pressed: F = 0, static start "
             "under -0.2 mm, then held; sliding: the same with F = 0.3; lifted: F = 0, 1 mm above the "
             "foundation. One process per case.", "",
             "| nodes | unknowns | contact nodes | scene | contact solve | set-up incl. static start [s] | substep [ms] | one solve [ms] | substep / solve | peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['nodes']} | {r['unknowns']} | {r['contact_nodes']} | {r['scene']} | "
                     f"{'sparse' if r['sparse'] else 'condensed'} | "
                     f"{r['static_start_seconds']:.3g} | {1e3 * r['substep_seconds']:.3g} | "
                     f"{1e3 * r['sparse_solve_seconds']:.3g} | {r['substep_per_solve']:.2f} | {r['peak_memory_mb']:.0f} |")
    (OUT / "cost3d.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
