"""What a mesh from a file costs (issue 43), measured through the FMU in one run, interleaved:

1. set-up: instantiation, reading, assembly, factorization and one 1e-6 s substep, for the
   rectangle (mesh = ""), the same rectangle from a Gmsh file, and an unstructured Gmsh mesh of
   about as many nodes (a plate with a hole), at about 1e4 and 1e5 nodes;
2. the substep: the damped sliding scene's substeps on the rectangle against the same body
   from a file (the same dofs and contact nodes), and on the unstructured mesh;
3. the reduced body (20 modes) on the rectangle and on the unstructured mesh: CPU time and
   the normal force's relative L2 error, each against its own full body.

Writes benchmarks/results/mesh_cost.json and mesh_cost.md.

    .venv/bin/python benchmarks/mesh_cost.py [--rounds N]
"""
import argparse
import json
import pathlib
import statistics
import tempfile
import time

import numpy as np
from fmpy import simulate_fmu

from contactbody import find_fmu, meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
SLIDING = {"friction_coefficient": 0.3, "damping_stiffness": 4e-6, "internal_step": 4e-6}


def seconds(start_values, stop_time, output=("normal_force",), interval=None):
    t0 = time.perf_counter()
    r = simulate_fmu(str(find_fmu()), start_values=start_values, stop_time=stop_time,
                     output_interval=interval or stop_time, output=list(output))
    return time.perf_counter() - t0, r


def nodes_of(path):
    with meshes.session("count") as gmsh:
        gmsh.open(str(path))
        return len(gmsh.model.mesh.getNodes()[0])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    result = {"rounds": args.rounds, "setup": [], "substep": {}, "reduced": {}}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        # 1. Set-up at about 1e4 and 1e5 nodes.
        for n in (99, 315):
            rect_file = meshes.rectangle(tmp / f"rect{n}.msh", nx=n, ny=n)
            target = (n + 1) ** 2
            size = 0.1 / n * 1.05
            hole = meshes.plate_with_hole(tmp / f"hole{n}.msh", width=0.1, height=0.1,
                                          hole=(0.05, 0.05, 0.02), size=size)
            bodies = {"rectangle": {"nx": n, "ny": n}, "rectangle from a file": {"mesh": str(rect_file)},
                      "plate with a hole": {"mesh": str(hole)}}
            times = {k: [] for k in bodies}
            for _ in range(args.rounds):
                for k, values in bodies.items():
                    times[k].append(seconds({**values, "internal_step": 1e-6, "mass_matrix": 0}, 1e-6)[0])
            result["setup"].append({"nodes_rectangle": target, "nodes_hole": nodes_of(hole),
                                    "file_MB": rect_file.stat().st_size / 1e6,
                                    "seconds": {k: statistics.median(v) for k, v in times.items()}})
        # 2. The substep at 21 x 21 nodes: 250 substeps of damped sliding.
        rect_file = meshes.rectangle(tmp / "rect20.msh", nx=20, ny=20)
        hole = meshes.plate_with_hole(tmp / "hole20.msh", width=0.1, height=0.1, hole=(0.05, 0.05, 0.02),
                                      size=0.0052)
        bodies = {"rectangle": {}, "rectangle from a file": {"mesh": str(rect_file)},
                  "plate with a hole": {"mesh": str(hole)}}
        stop = 250 * SLIDING["internal_step"]
        per = {k: [] for k in bodies}
        for _ in range(args.rounds):
            for k, values in bodies.items():
                setup = seconds({**values, **SLIDING, "internal_step": 1e-6}, 1e-6)[0]
                total = seconds({**values, **SLIDING}, stop)[0]
                per[k].append((total - setup) / 250)
        result["substep"] = {"nodes_hole": nodes_of(hole), "nodes_rectangle": 441,
                             "microseconds": {k: 1e6 * statistics.median(v) for k, v in per.items()}}
        # 3. The reduced body: 20 modes against the full body, 10 ms of damped sliding.
        for k, values in {"rectangle": {}, "plate with a hole": {"mesh": str(hole)}}.items():
            full_t, full = seconds({**values, **SLIDING}, 0.01, interval=1e-4)
            red_t, red = seconds({**values, **SLIDING, "modes": 20}, 0.01, interval=1e-4)
            error = float(np.linalg.norm(red["normal_force"] - full["normal_force"]) /
                          np.linalg.norm(full["normal_force"]))
            result["reduced"][k] = {"full_s": full_t, "reduced_s": red_t, "speedup": full_t / red_t,
                                    "normal_force_l2_error": error}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "mesh_cost.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "mesh_cost.md").write_text(report(result))
    print(report(result))


def report(r):
    lines = ["# What a mesh from a file costs", "",
             f"`.venv/bin/python benchmarks/mesh_cost.py --rounds {r['rounds']}`: through the FMU, "
             "medians of interleaved rounds.", "",
             "| nodes (rectangle / hole) | file [MB] | set-up, rectangle [s] | rectangle from a file [s] | plate with a hole [s] |",
             "|---|---|---|---|---|"]
    for s in r["setup"]:
        t = s["seconds"]
        lines.append(f"| {s['nodes_rectangle']} / {s['nodes_hole']} | {s['file_MB']:.1f} | {t['rectangle']:.2f} | "
                     f"{t['rectangle from a file']:.2f} | {t['plate with a hole']:.2f} |")
    s = r["substep"]
    lines += ["", f"Substep of damped sliding (rectangle 441 nodes, plate with a hole {s['nodes_hole']}):", "",
              "| body | µs per substep |", "|---|---|"]
    lines += [f"| {k} | {v:.0f} |" for k, v in s["microseconds"].items()]
    lines += ["", "Reduced body, 20 modes, 10 ms of damped sliding:", "",
              "| body | full [s] | reduced [s] | speed-up | normal force L2 error |", "|---|---|---|---|---|"]
    lines += [f"| {k} | {v['full_s']:.2f} | {v['reduced_s']:.2f} | {v['speedup']:.1f} | {v['normal_force_l2_error']:.2e} |"
              for k, v in r["reduced"].items()]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
