"""Where the reduced body's substep goes (issue 44): build/bench_contact_profile on damped
sliding from the static start (F = 0.3, beta = 4e-6 s, 20 m/s, one substep per step), 80 modes,
at nx = 20, 80, 160 (substep 2e-6 s) and at nx = 160 with the larger substeps that the
FMU's speed-up takes (8e-6 and 1.6e-5 s): microseconds per substep pressed (the whole edge in
contact) and lifted off (no contact solve), Newton iterations, residual evaluations (products
with the Delassus operator), Newton factorizations, factorization updates and node state
changes per substep; and the FMU's own cost per doStep (fmpy, one substep per doStep, against
the solver's substep; at 2e-6 s). Times are medians of 5 alternating rounds (pressed, lifted;
the FMU's of 3), from the run labelled "after (607f689)" on: single runs moved by 20 %.
Each run is stored under a label (the code it measured), so that the results file holds the
profile before and after a change:

    .venv/bin/python benchmarks/contact_profile.py --label LABEL [--build DIR] [--out benchmarks/results]

--build names the build whose bench_contact_profile and ContactBody.fmu are measured (default
build/, the portable one that users get).
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

MODES, DT, STEPS = 80, 2e-6, 1500
# (nx, substep): the FMU's doStep is measured at DT only.
RUNS = ((20, DT), (80, DT), (160, DT), (160, 8e-6), (160, 1.6e-5))


def profile(build, nx, dt, modes=MODES):
    steps = STEPS if dt == DT else 600
    out = subprocess.run([str(build / "bench_contact_profile"), str(nx), str(modes),
                          repr(dt), str(steps)], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def fmu_per_do_step(path, nx, modes=MODES, steps=1500):
    """CPU seconds per doStep through the FMU (fmpy), one substep per doStep."""
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
    rounds, k = [], 50
    for _ in range(3):
        t0 = time.process_time()
        for k in range(k, k + steps):
            fmu.doStep(k * DT, DT)
            fmu.getReal([vr["normal_force"], vr["energy"]])
        rounds.append((time.process_time() - t0) / steps)
        k += 1
    cpu = sorted(rounds)[1]
    fmu.terminate()
    fmu.freeInstance()
    return cpu * 1e6


def table(runs):
    lines = ["# The reduced body's substep, profiled", "",
             "`benchmarks/contact_profile.py`: damped sliding from the static start (F = 0.3, "
             f"β = 4e-6 s, 20 m/s), {MODES} modes, substep {DT:g} s, one substep per step; per "
             "substep: wall µs pressed (the edge in contact) and lifted off (no contact solve), "
             "Newton iterations, residual evaluations (each a product with W), Newton "
             "factorizations, factorization updates (Woodbury, from 7e6115a on) and node state "
             "changes; the FMU's CPU µs per doStep of one substep (fmpy, outputs read each "
             "step); and one product with the dense W alone (m × m, in the same process), the unit in which "
             "the pressed and lifted substeps are also given. Labels name the code and, where not "
             "the portable build/, the build. From \"after (607f689)\" on, times are medians of 5 "
             "alternating rounds (the FMU's of 3).", "",
             "| code | nx | unknowns | substep s | pressed µs | lifted µs | pressed / lifted | "
             "Newton its | W products | factorizations | updates | state changes | FMU doStep µs | "
             "one W product µs | pressed, in W products | lifted, in W products |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for label, rows in runs.items():
        for r in rows:
            fmu = r.get("fmu_do_step_us")
            lines.append(f"| {label} | {r['nx']} | {r['unknowns']} | {r['dt']:g} | "
                         f"{r['substep_us_pressed']:.0f} | "
                         f"{r['substep_us_lifted']:.0f} | "
                         f"{r['substep_us_pressed'] / r['substep_us_lifted']:.2f} | "
                         f"{r['newton_iterations']:.2f} | {r['residual_evaluations']:.2f} | "
                         f"{r['factorizations']:.3f} | "
                         + (f"{r['updates']:.3f}" if "updates" in r else "–") +
                         f" | {r['state_changes']:.3f} | "
                         + (f"{fmu:.0f}" if fmu is not None else "–") + " | "
                         + (f"{r['w_product_us']:.1f} | "
                            f"{r['substep_us_pressed'] / r['w_product_us']:.1f} | "
                            f"{r['substep_us_lifted'] / r['w_product_us']:.1f} |"
                            if "w_product_us" in r else "– | – | – |"))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--label", required=True, help="what code was measured")
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    fmu = args.build / "ContactBody.fmu" if args.build != ROOT / "build" else find_fmu()
    path = args.out / "contact_profile.json"
    runs = json.loads(path.read_text()) if path.exists() else {}
    rows = []
    for nx, dt in RUNS:
        r = profile(args.build, nx, dt)
        r["fmu_do_step_us"] = fmu_per_do_step(fmu, nx) if dt == DT else None
        rows.append(r)
    runs[args.label] = rows
    for r in (r for rows in runs.values() for r in rows):  # the ratios the prose quotes
        r["pressed_over_lifted"] = r["substep_us_pressed"] / r["substep_us_lifted"]
        if "w_product_us" in r:
            r["pressed_in_w_products"] = r["substep_us_pressed"] / r["w_product_us"]
            r["lifted_in_w_products"] = r["substep_us_lifted"] / r["w_product_us"]
    args.out.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(runs, indent=1))
    (args.out / "contact_profile.md").write_text(table(runs))
    print(table(runs))


if __name__ == "__main__":
    main()
