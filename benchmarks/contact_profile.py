"""Where the reduced body's substep goes (issue 44): build/bench_contact_profile on damped
sliding from the static start (F = 0.3, beta = 4e-6 s, 20 m/s, one substep per step), 80 modes,
at nx = 20, 80, 160 (substep 2e-6 s) and at nx = 160 with the larger substeps that the
FMU's speed-up takes (8e-6 and 1.6e-5 s): microseconds per substep pressed (the whole edge in
contact) and lifted off (no contact solve), Newton iterations, residual evaluations (products
with the Delassus operator), Newton factorizations, factorization updates and node state
changes per substep; and the FMU's own cost per doStep (one substep per doStep, against the
solver's substep; at 2e-6 s), through fmpy and through the FMU's C API (build/bench_fmu_do_step,
no interpreter). The matrix entries a substep reads (reads()) give the floor of pressed /
lifted where both run at one rate of reads. Times are medians of 5 alternating rounds (pressed, lifted;
the FMU's of 3), from the run labelled "after (607f689)" on: single runs moved by 20 %.
Each run is stored under a label (the code it measured), so that the results file holds the
profile before and after a change:

    .venv/bin/python benchmarks/contact_profile.py --label LABEL [--build DIR] [--out benchmarks/results]

--build names the build whose bench_contact_profile, bench_fmu_do_step and ContactBody.fmu are
measured (default build/, the portable one that users get).
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
# (nx, substep, reduced_edge): the FMU's doStep is measured at DT on the massless edge only.
# Edge 0 is by_variant, the massless edge for this scene's variant 1; 2 the tangential-mass
# edge (the default of variants 0, 3 and 4), from "native after (336cbe7)" on.
MASSLESS, TANGENTIAL_MASS = 0, 2
RUNS = ((20, DT, MASSLESS), (80, DT, MASSLESS), (160, DT, MASSLESS), (160, 8e-6, MASSLESS),
        (160, 1.6e-5, MASSLESS), (160, DT, TANGENTIAL_MASS))


def fmu_parameters(nx, modes):
    """The scene's parameters through the FMU: (integers, reals), by variable name; and the
    outputs read after each doStep. Both FMU timings use them."""
    return ({"nx": nx, "ny": nx, "modes": modes, "initial_state": 1},
            {"friction_coefficient": 0.3, "damping_stiffness": 4e-6, "internal_step": DT})


OUTPUTS = ("normal_force", "energy")


def profile(build, nx, dt, edge, modes=MODES):
    steps = STEPS if dt == DT else 600
    out = subprocess.run([str(build / "bench_contact_profile"), str(nx), str(modes),
                          repr(dt), str(steps), str(edge)],
                         check=True, capture_output=True, text=True).stdout
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
    integers, reals = fmu_parameters(nx, modes)
    fmu.setInteger([vr[name] for name in integers], list(integers.values()))
    fmu.setReal([vr[name] for name in reals], list(reals.values()))
    fmu.exitInitializationMode()
    for k in range(50):
        fmu.doStep(k * DT, DT)
    rounds, k = [], 50
    for _ in range(3):
        t0 = time.process_time()
        for k in range(k, k + steps):
            fmu.doStep(k * DT, DT)
            fmu.getReal([vr[name] for name in OUTPUTS])
        rounds.append((time.process_time() - t0) / steps)
        k += 1
    cpu = sorted(rounds)[1]
    fmu.terminate()
    fmu.freeInstance()
    return cpu * 1e6


def fmu_host_per_do_step(build, path, nx, modes=MODES, steps=STEPS):
    """CPU microseconds per doStep of the same FMU through its C API (build/bench_fmu_do_step),
    without an interpreter: the FMU's own cost, with the same parameters and outputs."""
    md = fmpy.read_model_description(str(path))
    unzipped = pathlib.Path(fmpy.extract(str(path)))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    library = unzipped / "binaries" / "linux64" / (md.coSimulation.modelIdentifier + ".so")
    integers, reals = fmu_parameters(nx, modes)
    setters = [f"i:{vr[name]}={value}" for name, value in integers.items()]
    setters += [f"r:{vr[name]}={value!r}" for name, value in reals.items()]
    outputs = ",".join(str(vr[name]) for name in OUTPUTS)
    out = subprocess.run([str(build / "bench_fmu_do_step"), str(library), md.guid, repr(DT),
                          str(steps), outputs, *setters],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["do_step_us"]


def trapezoid(rows, width):
    """Entries in the first `rows` rows of a lower trapezoid `width` wide (row i: min(i + 1, width))."""
    return sum(min(i + 1, width) for i in range(rows))


def lifted_reads(r):
    """Doubles a lifted substep reads: B_hat w on every contact row and B_hat u on the normal
    ones (B_hat's residual block is lower trapezoidal)."""
    nc, m, k = r["unknowns"] // 2, r["modes"], r["residual_modes"]
    return m * 2 * nc + trapezoid(2 * nc, k) + m * nc + trapezoid(nc, k)


def forces_reads(r, compacted):
    """Doubles the contact forces B_hat^T lambda read: B_hat's trapezoid on every contact row,
    or (compacted, 43d301c's code) B_hat^T's n_c compacted columns, their residual rows upper
    trapezoidal."""
    nc, m, k = r["unknowns"] // 2, r["modes"], r["residual_modes"]
    if compacted:
        return (m + min(nc, k)) * nc + trapezoid(nc, max(k - nc, 0))
    return m * 2 * nc + trapezoid(2 * nc, k)


def reads(r):
    """Doubles a substep reads from its matrices (the massless edge with friction, its nodes
    sliding): (lifted, pressed). Pressed adds to lifted, per residual evaluation, W_C
    (2 n_c x n_c) and the LU of the Newton system on the active nodes (active^2), and once the
    contact forces, compacted where the run says "compacted_forces"."""
    nc, lifted = r["unknowns"] // 2, lifted_reads(r)
    per_evaluation = 2 * nc * nc + r["active_nodes"] ** 2
    return lifted, (lifted + r["residual_evaluations"] * per_evaluation +
                    forces_reads(r, r.get("compacted_forces", False)))


def floor_reads(r):
    """The fewest doubles any pressed substep of this scene reads, whatever its solve: the
    lifted one's, the forces compacted, and per residual evaluation the Newton system's LU on
    the active nodes and a check of the rows the system does not fix (the slipping nodes'
    tangential rows and the open nodes' normal ones, n_c rows in all) against the active
    nodes' compacted columns."""
    nc, active = r["unknowns"] // 2, r["active_nodes"]
    return (lifted_reads(r) + forces_reads(r, True) +
            r["residual_evaluations"] * (nc * active + active ** 2))


def derive(runs):
    """The ratios the prose quotes, for every run."""
    for rows in runs.values():
        for r in rows:
            r["pressed_over_lifted"] = r["substep_us_pressed"] / r["substep_us_lifted"]
            if "residual_modes" in r and r["edge"] == MASSLESS:
                lifted, pressed = reads(r)
                r["reads_lifted"], r["reads_pressed"] = lifted, pressed
                r["reads_ratio"] = pressed / lifted
                r["floor_reads_ratio"] = floor_reads(r) / lifted
            if "w_product_us" in r:
                r["pressed_in_w_products"] = r["substep_us_pressed"] / r["w_product_us"]
                r["lifted_in_w_products"] = r["substep_us_lifted"] / r["w_product_us"]


def table(runs):
    lines = ["# The reduced body's substep, profiled", "",
             "`benchmarks/contact_profile.py`: damped sliding from the static start (F = 0.3, "
             f"β = 4e-6 s, 20 m/s), {MODES} modes, substep {DT:g} s, one substep per step, on the "
             "massless edge (variant 1's) and, where the edge column says so, the tangential-mass "
             "edge (the default of variants 0, 3 and 4); per substep: wall µs pressed (the edge in contact) and lifted off (no contact solve), "
             "Newton iterations, residual evaluations (each a product with W), Newton "
             "factorizations, factorization updates (Woodbury, from 7e6115a on) and node state "
             "changes; the FMU's CPU µs per doStep of one substep (outputs read each step), "
             "through fmpy and, from \"after (43d301c)\" on, through its C API "
             "(build/bench_fmu_do_step, no interpreter); the matrix entries each substep reads "
             "(`reads()` in the script: lifted B_hat w and B_hat u; pressed adds W_C and the "
             "Newton system's LU per residual evaluation and the forces' B_hat^T once, compacted "
             "in 43d301c only), as a ratio, the floor of pressed / lifted where both run at one "
             "rate of reads, and the same ratio at the floor of any solve (`floor_reads()`: the forces "
             "compacted, the check on the rows the Newton system does not fix); and one product with the dense W alone (m × m, in the same process), the unit in which "
             "the pressed and lifted substeps are also given. Labels name the code and, where not "
             "the portable build/, the build. From \"after (607f689)\" on, times are medians of 5 "
             "alternating rounds (the FMU's of 3).", "",
             "| code | nx | unknowns | substep s | edge | pressed µs | lifted µs | pressed / lifted | "
             "Newton its | W products | factorizations | updates | state changes | FMU doStep µs | "
             "FMU doStep µs, C host | pressed / lifted in reads | any solve's floor, in reads | "
             "one W product µs | pressed, in W products | lifted, in W products |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for label, rows in runs.items():
        for r in rows:
            fmu = r.get("fmu_do_step_us")
            edge = "tangential mass" if r.get("edge") == TANGENTIAL_MASS else "massless"
            lines.append(f"| {label} | {r['nx']} | {r['unknowns']} | {r['dt']:g} | {edge} | "
                         f"{r['substep_us_pressed']:.0f} | "
                         f"{r['substep_us_lifted']:.0f} | "
                         f"{r['pressed_over_lifted']:.2f} | "
                         f"{r['newton_iterations']:.2f} | {r['residual_evaluations']:.2f} | "
                         f"{r['factorizations']:.3f} | "
                         + (f"{r['updates']:.3f}" if "updates" in r else "–") +
                         f" | {r['state_changes']:.3f} | "
                         + (f"{fmu:.0f}" if fmu is not None else "–") + " | "
                         + (f"{r['fmu_host_do_step_us']:.0f}" if r.get("fmu_host_do_step_us") else "–")
                         + " | " + (f"{r['reads_ratio']:.2f}" if "reads_ratio" in r else "–") + " | "
                         + (f"{r['floor_reads_ratio']:.2f}" if "floor_reads_ratio" in r else "–") + " | "
                         + (f"{r['w_product_us']:.1f} | "
                            f"{r['pressed_in_w_products']:.1f} | "
                            f"{r['lifted_in_w_products']:.1f} |"
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
    for nx, dt, edge in RUNS:
        r = profile(args.build, nx, dt, edge)
        through_fmu = dt == DT and edge == MASSLESS
        r["fmu_do_step_us"] = fmu_per_do_step(fmu, nx) if through_fmu else None
        r["fmu_host_do_step_us"] = fmu_host_per_do_step(args.build, fmu, nx) if through_fmu else None
        rows.append(r)
    runs[args.label] = rows
    derive(runs)
    args.out.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(runs, indent=1))
    (args.out / "contact_profile.md").write_text(table(runs))
    print(table(runs))


if __name__ == "__main__":
    main()
