"""Where the reduced body's substep goes (issue 44): build/bench_contact_profile on damped
sliding from the static start (F = 0.3, beta = 4e-6 s, 20 m/s, one substep per step), 80 modes,
at nx = 20, 80, 160 (substep 2e-6 s): microseconds per substep pressed (the whole edge in
contact) and lifted off (no contact solve), Newton iterations, residual evaluations (products
with the Delassus operator), Newton factorizations and node state changes per substep; and
the FMU's own cost per doStep (fmpy, one substep per doStep, against the solver's substep).
Each run is stored under a label (the code it measured), so that the results file holds the
profile before and after a change:

    .venv/bin/python benchmarks/contact_profile.py --label LABEL [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import subprocess
import sys
import time

import fmpy
from fmpy.fmi2 import FMU2Slave

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from contactbody.fmu import find_fmu  # noqa: E402

MESHES = (20, 80, 160)
MODES, DT, STEPS = 80, 2e-6, 1500


def profile(nx, modes=MODES):
    out = subprocess.run([str(ROOT / "build" / "bench_contact_profile"), str(nx), str(modes),
                          repr(DT), str(STEPS)], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def fmu_per_do_step(nx, modes=MODES, steps=1500):
    """CPU seconds per doStep through the FMU (fmpy), one substep per doStep."""
    path = find_fmu()
    md = fmpy.read_model_description(str(path))
    unzipped = fmpy.extract(str(path))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="profile")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0)
    fmu.enterInitializationMode()
    fmu.setInteger([vr["nx"], vr["ny"], vr["modes"], vr["initial_state"]], [nx, nx, modes, 1])
    fmu.setReal([vr["friction_coefficient"], vr["damping_stiffness"], vr["internal_step"]],
                [0.3, 4e-6, DT])
    fmu.exitInitializationMode()
    for k in range(50):
        fmu.doStep(k * DT, DT)
    t0 = time.process_time()
    for k in range(50, 50 + steps):
        fmu.doStep(k * DT, DT)
        fmu.getReal([vr["normal_force"], vr["energy"]])
    cpu = (time.process_time() - t0) / steps
    fmu.terminate()
    fmu.freeInstance()
    return cpu * 1e6


def table(runs):
    lines = ["# The reduced body's substep, profiled", "",
             "`benchmarks/contact_profile.py`: damped sliding from the static start (F = 0.3, "
             f"β = 4e-6 s, 20 m/s), {MODES} modes, substep {DT:g} s, one substep per step; per "
             "substep: wall µs pressed (the edge in contact) and lifted off (no contact solve), "
             "Newton iterations, residual evaluations (each a product with W), Newton "
             "factorizations and node state changes; the FMU's CPU µs per doStep of one "
             "substep (fmpy, outputs read each step).", "",
             "| code | nx | unknowns | pressed µs | lifted µs | pressed / lifted | Newton its | "
             "W products | factorizations | state changes | FMU doStep µs |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for label, rows in runs.items():
        for r in rows:
            lines.append(f"| {label} | {r['nx']} | {r['unknowns']} | {r['substep_us_pressed']:.0f} | "
                         f"{r['substep_us_lifted']:.0f} | "
                         f"{r['substep_us_pressed'] / r['substep_us_lifted']:.2f} | "
                         f"{r['newton_iterations']:.2f} | {r['residual_evaluations']:.2f} | "
                         f"{r['factorizations']:.3f} | {r['state_changes']:.3f} | "
                         f"{r['fmu_do_step_us']:.0f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--label", required=True, help="what code was measured")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    path = args.out / "contact_profile.json"
    runs = json.loads(path.read_text()) if path.exists() else {}
    rows = []
    for nx in MESHES:
        r = profile(nx)
        r["fmu_do_step_us"] = fmu_per_do_step(nx)
        rows.append(r)
    runs[args.label] = rows
    args.out.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(runs, indent=1))
    (args.out / "contact_profile.md").write_text(table(runs))
    print(table(runs))


if __name__ == "__main__":
    main()
