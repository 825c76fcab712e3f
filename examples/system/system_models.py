"""The body in system models: a belt drive under it (BeltDrive.fmu) and a press on top
(Press.fmu), run three ways from one description (contactbody.system):
  - as an SSP with fmpy's simulate_ssp (fixed step, Jacobi),
  - as an fmpy container FMU with fmpy's simulate_fmu,
  - with contactbody.master: fixed step (held or extrapolated inputs), adaptive (step
    doubling, or the inputs' extrapolation error), and strongly coupled (iterated).
Writes the .ssp and container FMUs to OUT, and to RESULTS: system.png (belt speed, friction
force, stick/slip of the bottom edge, press force), system.md and system.json (accuracy
against cost; where the fixed step fails). Prints the numbers.

    .venv/bin/python examples/system/system_models.py [--out DIR] [--results DIR | --refresh]
"""
import argparse
import json
import pathlib
import time

import matplotlib
import numpy as np

matplotlib.use("Agg")
import fmpy  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

from contactbody import system as S  # noqa: E402
from contactbody.fmu import SimulationFailed  # noqa: E402
from contactbody.master import Master  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
STOP = 0.01
LADDER = [1e-4, 5e-5, 2.5e-5, 1.25e-5, 6.25e-6]
REFERENCE = 3.125e-6  # the body's internal step: one substep per communication step


def error(r, ref, name="belt.belt_velocity"):
    return float(np.abs(r[name] - np.interp(r["time"], ref["time"], ref[name])).max())


def belt_study(m):
    """Accuracy (sup error of the belt velocity against the finest fixed step) against cost
    (doStep calls, wall time) for the fixed and adaptive masters."""
    ref = m.run_fixed(STOP, REFERENCE)
    rows = []

    def row(master, setting, r, tic, **extra):
        return {"master": master, "setting": setting, "error": error(r, ref),
                "bond_mismatch": float(abs(r["belt.load_work"][-1] -
                                           S.WIDTH * r["body.foundation_work"][-1])),
                "do_steps": m.do_steps, **extra, "seconds": time.perf_counter() - tic}

    for extrapolate in (False, True):
        for h in LADDER:
            tic = time.perf_counter()
            r = m.run_fixed(STOP, h, extrapolate=extrapolate)
            rows.append(row("fixed" + (", extrapolated" if extrapolate else ""), f"h = {h:g}",
                            r, tic))
    for estimator in ("doubling", "input"):
        for extrapolate in (False, True):
            for tol in (1e-2, 3e-3, 1e-3, 3e-4):
                tic = time.perf_counter()
                r = m.run_adaptive(STOP, rtol=tol, atol=tol, h0=1e-5, h_min=REFERENCE,
                                   h_max=1e-3, extrapolate=extrapolate, estimator=estimator)
                rows.append(row(f"adaptive ({estimator}"
                                f"{', extrapolated' if extrapolate else ''})", f"tol = {tol:g}",
                                r, tic, accepted=m.accepted, rejected=m.rejected))
    return ref, rows


PRESS_STOP = 0.03


def press_study(m):
    out = []
    for h in (1e-4, 5e-5, 2.5e-5, 1.25e-5):
        try:
            r = m.run_fixed(PRESS_STOP, h)
        except SimulationFailed as e:  # diverged: the body's step fails and says why
            out.append({"master": "fixed (explicit)", "h": h, "failed": str(e).split(": ", 1)[-1],
                        "do_steps": m.do_steps})
            continue
        out.append({"master": "fixed (explicit)", "h": h, "energy_max": float(r["body.energy"].max()),
                    "energy_max_last_third": float(r["body.energy"][2 * len(r) // 3:].max()),
                    "position_end": float(r["press.position"][-1]), "do_steps": m.do_steps})
    for h in (1e-4, 5e-5, 2.5e-5):
        r = m.run_fixed(PRESS_STOP, h, iterate=True, tolerance=1e-6)
        out.append({"master": "strongly coupled", "h": h,
                    "energy_max": float(r["body.energy"].max()),
                    "energy_max_last_third": float(r["body.energy"][2 * len(r) // 3:].max()),
                    "position_end": float(r["press.position"][-1]), "do_steps": m.do_steps,
                    "iterations_mean": float(np.mean(m.iterations)),
                    "iterations_max": int(max(m.iterations))})
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=HERE.parent / "output" / "system")
    parser.add_argument("--results", type=pathlib.Path, default=None,
                        help="where system.md, .json, .png go (default: the --out folder)")
    parser.add_argument("--refresh", action="store_true",
                        help="write them to examples/results, the committed copies")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    if args.results is None:  # a run leaves the checkout clean unless asked to refresh
        args.results = HERE.parent / "results" if args.refresh else args.out
    args.results.mkdir(parents=True, exist_ok=True)
    belt, press = S.belt_system(), S.press_system()

    ssp = S.write_ssp(belt, args.out / "belt_and_body.ssp", "BeltAndBody", STOP)
    S.write_ssp(press, args.out / "press_and_body.ssp", "PressAndBody", PRESS_STOP)
    container = S.write_container(belt, args.out / "belt_and_body_container.fmu", 1e-4,
                                  stop_time=STOP)
    via_ssp = S.simulate_ssp(ssp, STOP, 1e-4)
    via_container = fmpy.simulate_fmu(str(container))  # its DefaultExperiment: STOP at 1e-4 s
    with Master(belt) as m:
        # simulate_ssp starts the inputs at 0, the container at the sources' outputs at t0
        same_step = m.run_fixed(STOP, 1e-4, zero_inputs=True)
        n = len(same_step) - 1  # simulate_ssp adds up time and may take one step more
        agree = {"ssp": bool(np.array_equal(via_ssp["belt.belt_velocity"][:n],
                                            same_step["belt.belt_velocity"][1:])),
                 "container": bool(np.array_equal(via_container["belt_belt_velocity"],
                                                  m.run_fixed(STOP, 1e-4)["belt.belt_velocity"]))}
        print(f"at h = 1e-4 the SSP, the container FMU and the master agree bit for bit: {agree}")
        ref, rows = belt_study(m)
    with Master(press) as m:
        press_rows = press_study(m)
        press_fine = m.run_fixed(PRESS_STOP, 1.25e-5)
        press_iterated = m.run_fixed(PRESS_STOP, 1e-4, iterate=True)

    md = ["# System models (examples/system/system_models.py)", "",
          f"Belt drive + body, {STOP * 1e3:g} ms; error: sup over the communication points of "
          f"|belt velocity - the fixed step at {REFERENCE:g} s|; bond mismatch: |load_work - "
          "width x foundation_work| at the end (J).", "",
          "| master | setting | error (m/s) | bond mismatch (J) | doSteps | accepted / rejected | s |",
          "|---|---|---|---|---|---|---|"]
    for r in rows:
        ar = f"{r['accepted']} / {r['rejected']}" if "accepted" in r else ""
        md.append(f"| {r['master']} | {r['setting']} | {r['error']:.2e} | {r['bond_mismatch']:.2e} "
                  f"| {r['do_steps']} | {ar} | {r['seconds']:.2f} |")
    md += ["", f"Press + body, {PRESS_STOP * 1e3:g} ms (explicit: the press's position drives "
           "the top edge, the body's reaction comes back one step late; strongly coupled: each "
           "step iterated until both agree):", "",
           "| master | h (s) | max energy (J/m) | max energy, last third | press position at the end (m) | doSteps | iterations (mean / max) |",
           "|---|---|---|---|---|---|---|"]
    failures = []
    for r in press_rows:
        if "failed" in r:
            failures.append(f"- h = {r['h']:g}: {r['failed'][:400]}")
            md.append(f"| {r['master']} | {r['h']:g} | failed (below) | | | {r['do_steps']} | |")
            continue
        it = f"{r['iterations_mean']:.1f} / {r['iterations_max']}" if "iterations_mean" in r else ""
        md.append(f"| {r['master']} | {r['h']:g} | {r['energy_max']:.3g} "
                  f"| {r['energy_max_last_third']:.3g} | {r['position_end']:.4g} "
                  f"| {r['do_steps']} | {it} |")
    if failures:
        md += ["", "The explicit runs that diverged end in the body's fmi2Error:", "", *failures]
    (args.results / "system.md").write_text("\n".join(md) + "\n")
    (args.results / "system.json").write_text(json.dumps(
        {"agree_at_1e-4": agree, "belt": rows, "press": press_rows}, indent=1))
    print("\n".join(md))

    fig, ax = plt.subplots(2, 2, figsize=(11, 7))
    t = ref["time"] * 1e3
    ax[0, 0].plot(t, ref["belt.belt_velocity"], label=f"master, h = {REFERENCE:g} s")
    ax[0, 0].plot(via_ssp["time"] * 1e3 + 0.1, via_ssp["belt.belt_velocity"], ":",
                  label="simulate_ssp, h = 1e-4 s (fmpy labels the step's start)")
    ax[0, 0].set(title="belt velocity [m/s]", xlabel="t [ms]")
    ax[0, 0].legend(fontsize=7)
    ax[0, 1].plot(t, ref["body.friction_force"] / 1e3, label="friction force")
    ax[0, 1].plot(t, 0.3 * ref["body.normal_force"] / 1e3, ":", label="0.3 x normal force")
    ax[0, 1].set(title="body: friction force [kN/m]", xlabel="t [ms]")
    ax[0, 1].legend(fontsize=7)
    ax[1, 0].plot(t, ref["body.slipping_contact_nodes"], label="slipping")
    ax[1, 0].plot(t, ref["body.active_contact_nodes"], ":", label="in contact")
    ax[1, 0].set(title="bottom edge: stick and slip (nodes)", xlabel="t [ms]")
    ax[1, 0].legend(fontsize=7)
    ax[1, 1].plot(press_fine["time"] * 1e3, press_fine["press.reaction_force"],
                  label="explicit, h = 1.25e-5 s")
    ax[1, 1].plot(press_iterated["time"] * 1e3, press_iterated["press.reaction_force"], "--",
                  label="strongly coupled, h = 1e-4 s")
    ax[1, 1].plot(press_fine["time"] * 1e3, -press_fine["press.actuator_force"], ":",
                  label="actuator force")
    ax[1, 1].set(title="press: force of the body on the press [N]", xlabel="t [ms]")
    ax[1, 1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.results / "system.png", dpi=100)


if __name__ == "__main__":
    main()
