"""What a 3D body costs (issue 55): hemispheres of tetrahedra (benchmarks/hertz3d.py's shape) from
5k to 53k nodes, F = 0, damped (beta = 4e-6 s), 1e-6 s substeps, solved as the FMU would
(the cost model's contact solve, the factor kernel's rule). Two scenes per mesh:

* pressed: the static start under a clamp displacement of -0.2 mm (Hertz's load), then held;
* lifted: the same body 1 mm above the foundation (no contact: the floor).

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
SCENES = {"pressed": ["-2e-4", "0"], "lifted": ["-2e-4", "1e-3"]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--largest", type=int, default=len(MESHES), help="how many meshes, smallest first")
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
                out = subprocess.run([str(program), str(path), "0", "automatic", "30", "0", "3", *extra],
                                     check=True, capture_output=True, text=True).stdout
                row = {"nodes": nodes, "scene": scene, "contact_size": contact, **json.loads(out)}
                rows.append(row)
                print(json.dumps(row))
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "cost3d.json").write_text(json.dumps({"rows": rows}, indent=1) + "\n")
    lines = ["# What a 3D body costs", "",
             "`.venv/bin/python benchmarks/cost3d.py`: tetrahedral hemispheres (R = 50 mm), F = 0, "
             "beta = 4e-6 s, 1e-6 s substeps; pressed: static start under -0.2 mm, then held; lifted: "
             "1 mm above the foundation. One process per case.", "",
             "| nodes | unknowns | contact nodes | scene | set-up incl. static start [s] | substep [ms] | one solve [ms] | substep / solve | peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['nodes']} | {r['unknowns']} | {r['contact_nodes']} | {r['scene']} | "
                     f"{r['static_start_seconds']:.3g} | {1e3 * r['substep_seconds']:.3g} | "
                     f"{1e3 * r['sparse_solve_seconds']:.3g} | {r['substep_per_solve']:.2f} | {r['peak_memory_mb']:.0f} |")
    (OUT / "cost3d.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
