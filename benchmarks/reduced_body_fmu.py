"""The reduced body through the FMU, as users run it (fmpy, 1e-4 s communication steps): the
damped sliding scene from the static start (the paper's body, F = 0.3, beta = 4e-6 s, 20 m/s,
the top held, redistributed_normal) over 5 ms at nx = ny = 20, 40, 80, 160, the full body at
each mesh's usual step (4e-6 s x 20 / nx) against `modes` = 20, 40, 80 at that step and 2, 4, 8, 16
and 32x it (up to the communication step). Per run: the initialization's wall time (the reduced body's basis), the steps' CPU seconds
per simulated second (and wall), and the errors of normal force, friction force and energy (L2
over the communication steps, relative to the full body on the same mesh), all measured in one
run. The goals (issue 44: within 1 % of the full body, at least 300x at nx = 160, real time at
nx = 40) are checked against the run's own numbers.

    .venv/bin/python benchmarks/reduced_body_fmu.py [--meshes 20,40,80,160] [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import sys
import tempfile
import time

import fmpy
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from contactbody.fmu import Instance, find_fmu  # noqa: E402

H, STOP = 1e-4, 5e-3
OUTPUTS = ("normal_force", "friction_force", "energy")
MODES = (20, 40, 80)
FACTORS = (1, 2, 4, 8, 16, 32)


def run(md, unzipped, values):
    """Initializes and steps to STOP; returns (init seconds, step seconds, outputs per step)."""
    vr = {v.name: v.valueReference for v in md.modelVariables}
    types = {v.name: v.type for v in md.modelVariables}
    inst = Instance(md, unzipped, "bench")
    t0 = time.perf_counter()
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    for k, v in values.items():
        (inst.setReal if types[k] == "Real" else inst.setInteger)([vr[k]], [v])
    inst.exitInitializationMode()
    t1, c1 = time.perf_counter(), time.process_time()
    rows = []
    refs = [vr[n] for n in OUTPUTS]
    for k in range(round(STOP / H)):
        inst.doStep(k * H, H)
        rows.append(inst.getReal(refs))
    t2, c2 = time.perf_counter(), time.process_time()
    inst.close()
    return t1 - t0, (t2 - t1, c2 - c1), np.array(rows)


def l2(x, ref):
    """The relative L2 difference of two time series (also benchmarks/mass_carrying.py's)."""
    return float(np.sqrt(np.sum((x - ref) ** 2) / np.sum(ref ** 2)))


def measure(md, unzipped, nx):
    dt = 4e-6 * 20 / nx
    scene = dict(nx=nx, ny=nx, friction_coefficient=0.3, damping_stiffness=4e-6, internal_step=dt,
                 initial_state=1)
    init, (wall, cpu), ref = run(md, unzipped, scene)
    result = {"nx": nx, "dt": dt, "full": {"init_s": init, "wall_per_simulated_s": wall / STOP,
                                           "cpu_per_simulated_s": cpu / STOP},
              "reduced": []}
    for m in MODES:
        for factor in (f for f in FACTORS if dt * f <= H):
            init_r, (wall_r, cpu_r), x = run(md, unzipped, {**scene, "modes": m,
                                                            "internal_step": dt * factor})
            entry = {"modes": m, "dt": dt * factor, "init_s": init_r,
                     "wall_per_simulated_s": wall_r / STOP, "cpu_per_simulated_s": cpu_r / STOP,
                     "speedup": cpu / cpu_r}
            for i, name in enumerate(OUTPUTS):
                entry[f"error_{name}"] = l2(x[:, i], ref[:, i])
            result["reduced"].append(entry)
    return result


def table(results):
    lines = ["The reduced body through the FMU (fmpy, 1e-4 s steps), damped sliding from the "
             "static start, 5 ms (`benchmarks/reduced_body_fmu.py`; CPU seconds per simulated "
             "second of the steps, both bodies measured in one run; speed-up in CPU time; errors "
             "L2 over the steps relative to the full body on the same mesh; init: the "
             "initialization's wall time, the reduced body's basis included):", "",
             "| nx | full [s/s] | modes | dt [s] | reduced [s/s] | speed-up | normal force error "
             "| friction force error | energy error | init [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        for x in r["reduced"]:
            lines.append(
                f"| {r['nx']} | {r['full']['cpu_per_simulated_s']:.3g} | {x['modes']} | "
                f"{x['dt']:.3g} | {x['cpu_per_simulated_s']:.3g} | {x['speedup']:.1f} | "
                f"{x['error_normal_force']:.2e} | {x['error_friction_force']:.2e} | "
                f"{x['error_energy']:.2e} | {x['init_s']:.2f} |")
    lines.append("")
    for r in results:
        best = fastest_within(r)
        if best is None:
            lines.append(f"- nx = {r['nx']}: no reduced run within 1 % of the full body.")
            continue
        goal = {160: " (issue 44: at least 300x; the goal 1000x)",
                40: " (issue 44: real time, at most 1 CPU s per simulated s)"}.get(r["nx"], "")
        lines.append(f"- nx = {r['nx']}, fastest within 1 %: modes = {best['modes']}, dt = "
                     f"{best['dt']:.3g} s, {best['cpu_per_simulated_s']:.3g} CPU s per simulated s, "
                     f"{best['speedup']:.0f}x the full body{goal}.")
    return "\n".join(lines) + "\n"


def fastest_within(result, tolerance=0.01):
    """The cheapest reduced run whose three errors are within the tolerance, or None."""
    within = [x for x in result["reduced"] if max(x[f"error_{n}"] for n in OUTPUTS) <= tolerance]
    return min(within, key=lambda x: x["cpu_per_simulated_s"]) if within else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default="20,40,80,160")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    fmu = find_fmu()
    md = fmpy.read_model_description(str(fmu))
    unzipped = tempfile.mkdtemp(prefix="reduced_body_fmu_")
    fmpy.extract(str(fmu), unzipped)
    results = [measure(md, unzipped, int(nx)) for nx in args.meshes.split(",")]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "reduced_body_fmu.json").write_text(json.dumps(results, indent=1))
    (args.out / "reduced_body_fmu.md").write_text(table(results))
    print(table(results))


if __name__ == "__main__":
    main()
