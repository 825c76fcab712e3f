"""The supernodal factor's kernel sets as users get them: ContactBody3D.fmu's linux64 binary (the
portable build, zig's clang), driven through fmpy, on the 2.7k and 12.6k-node hemispheres of
cost3d.py pressed from the static start (F = 0, clamp displacement -0.2 mm, beta = 4e-6 s,
1e-6 s substeps). For each body, baseline_kernels = 1 (the baseline set: what the FMU ran on
Linux until 2026-12-07, docs/decisions.md "The factor's kernels for the CPU it runs on") and 0
(the fastest set this CPU has), alternated, the best of two: the set-up (instantiation through
exitInitializationMode: the discretization, the factor and the static start) and the mean
substep over 100 substeps after the first (one doStep of 1e-4 s); the kernel set the log names.

Writes benchmarks/results/fmu_kernels.{json,md}.

    .venv/bin/python benchmarks/fmu_kernels.py
"""
import json
import pathlib
import tempfile
import time

import fmpy

from contactbody import meshes
from contactbody.fmu import Instance

ROOT = pathlib.Path(__file__).resolve().parents[1]
FMU = ROOT / "build" / "ContactBody3D.fmu"
OUT = ROOT / "benchmarks" / "results"
BODIES = [("2.7k nodes", 5e-4), ("12.6k nodes", 2.5e-4)]
SCENE = {"friction_coefficient": 0.0, "initial_state": 1, "top_displacement": -2e-4,
         "internal_step": 1e-6, "damping_stiffness": 4e-6}


def run(description, unzipped, start):
    """(set-up s, substep s, the log's kernel set) of one instance."""
    tic = time.perf_counter()
    inst = Instance(description, unzipped, "kernels", logging_on=True)
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.set_values(start)
        inst.exitInitializationMode()
        setup = time.perf_counter() - tic
        inst.doStep(0, 1e-6)
        tic = time.perf_counter()
        inst.doStep(1e-6, 1e-4)
        substep = (time.perf_counter() - tic) / 100
        line = next(m[2] for m in inst.messages if m[2].startswith("contact solve:"))
        return setup, substep, line.split("flops of factorization): ")[1].rsplit(", ", 1)[0]
    finally:
        inst.close()


def main():
    description = fmpy.read_model_description(str(FMU))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        unzipped = fmpy.extract(str(FMU), tmp + "/fmu")
        for name, h in BODIES:
            mesh = meshes.hemisphere(pathlib.Path(tmp) / f"h{h}.msh", radius=0.05, contact_size=h,
                                     far_size=1e-2, fine_distance=0.0045, refine_distance=0.025,
                                     contact_angle=25.0)
            best = {}
            for _ in range(2):
                for baseline in (1, 0):
                    got = run(description, unzipped, {**SCENE, "mesh": str(mesh), "baseline_kernels": baseline})
                    old = best.get(baseline)
                    best[baseline] = (min(got[0], old[0]), min(got[1], old[1]), got[2]) if old else got
            row = {"body": name, "contact_size": h,
                   **{f"{key}_{b}": best[b][i] for b in (1, 0)
                      for i, key in enumerate(["setup_seconds", "substep_seconds", "kernel_set"])}}
            rows.append(row)
            print(json.dumps(row), flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "fmu_kernels.json").write_text(json.dumps({"rows": rows}, indent=1))
    lines = ["# The FMU's kernel sets", "",
             "`benchmarks/fmu_kernels.py`: ContactBody3D.fmu's linux64 binary through fmpy, a hemisphere "
             "pressed from the static start; baseline_kernels = 1 (what the FMU ran on Linux until "
             "2026-12-07) against 0 (the fastest set this CPU has), the best of two, alternated.", "",
             "| body | kernel set: baseline_kernels = 1 / 0 | set-up s: 1 / 0 | set-up 1 over 0 | "
             "substep ms: 1 / 0 | substep 1 over 0 |", "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['body']} | {r['kernel_set_1']} / {r['kernel_set_0']} | "
                     f"{r['setup_seconds_1']:.3g} / {r['setup_seconds_0']:.3g} | "
                     f"{r['setup_seconds_1'] / r['setup_seconds_0']:.2f}× | "
                     f"{1e3 * r['substep_seconds_1']:.3g} / {1e3 * r['substep_seconds_0']:.3g} | "
                     f"{r['substep_seconds_1'] / r['substep_seconds_0']:.2f}× |")
    (OUT / "fmu_kernels.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
