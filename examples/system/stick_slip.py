"""Stick-slip in a system: the belt drive under the body, its motor held at
a speed by a proportional controller (BeltDrive's speed_setpoint, speed_gain), the interface a
Stribeck law with Rayleigh damping in the body. The pulley sticks to the body, the shaft winds
up until the edge breaks loose near F_s, the belt races ahead, slows and sticks again: a
stick-slip limit cycle. Its period and amplitude (the belt's peak speed per cycle) along three
ladders: the coupling step, the body's internal step and the mesh.

Cycles start where the belt speed rises through the drive speed (pulley_radius x
speed_setpoint); the first two are dropped (the start from rest), the rest averaged.

Writes RESULTS/stick_slip.{json,md,png}.

    .venv/bin/python examples/system/stick_slip.py [--results DIR] [--stop T]
"""
import argparse
import json
import pathlib
import time

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from contactbody import system as S  # noqa: E402
from contactbody.master import Master  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
# The interface: F falls from F_s = 0.6 at rest to F_d = 0.3 over v_s = 0.3 m/s.
LAW = {"friction_coefficient": 0.3, "static_friction_ratio": 2.0, "stribeck_velocity": 0.3}
# A heavier pulley on a softer shaft than the belt study's, driven at 20 rad/s (1 m/s belt).
BELT = {"pulley_inertia": 1e-3, "shaft_stiffness": 20.0, "speed_setpoint": 20.0,
        "speed_gain": 10.0, "torque_amplitude": 0.0, "torque_ramp_time": 5e-3}
DRIVE_SPEED = 0.05 * BELT["speed_setpoint"]  # m/s: pulley_radius x setpoint
STOP = 1.5
BASE = {"step": 2.5e-5, "internal_step": 3.125e-6, "nx": 10}
LADDERS = {"step": [1e-4, 5e-5, 2.5e-5, 1.25e-5, 6.25e-6],
           "internal_step": [6.25e-6, 3.125e-6, 1.5625e-6],
           "nx": [5, 10, 20]}


def run(step, internal_step, nx, stop=STOP):
    system = S.belt_system(**LAW, nx=nx, ny=nx, internal_step=internal_step)
    system.parameters.update({f"belt.{k}": v for k, v in BELT.items()})
    system.record = system.record + ["belt.shaft_torque", "belt.motor_speed"]
    tic = time.perf_counter()
    with Master(system) as m:
        r = m.run_fixed(stop, step)
    return r, time.perf_counter() - tic


def cycles(r, skip=2):
    """Per cycle (between upward crossings of the drive speed): period, peak and lowest belt
    speed, largest friction ratio T/N and the time the belt spends below 5 % of the drive
    speed (sticking)."""
    t, v = r["time"], r["belt.belt_velocity"]
    up = np.flatnonzero((v[:-1] < DRIVE_SPEED) & (v[1:] >= DRIVE_SPEED))
    crossing = t[up] + (DRIVE_SPEED - v[up]) / (v[up + 1] - v[up]) * (t[up + 1] - t[up])
    ratio = r["body.friction_force"] / np.maximum(r["body.normal_force"], 1e-300)
    out = []
    for a, b in zip(crossing[skip:-1], crossing[skip + 1:]):
        k = (t >= a) & (t < b)
        out.append({"start": float(a), "period": float(b - a), "peak": float(v[k].max()),
                    "lowest": float(v[k].min()), "max_ratio": float(ratio[k].max()),
                    "stuck": float(np.mean(np.abs(v[k]) < 0.05 * DRIVE_SPEED) * (b - a))})
    return out


def summary(r, seconds, **setting):
    c = cycles(r)
    period = np.array([x["period"] for x in c])
    peak = np.array([x["peak"] for x in c])
    whole = (r["time"] >= c[0]["start"]) & (r["time"] < c[-1]["start"] + c[-1]["period"])
    return {**setting, "cycles": len(c), "period": float(period.mean()),
            "period_std": float(period.std()), "peak": float(peak.mean()),
            "peak_std": float(peak.std()), "lowest": float(min(x["lowest"] for x in c)),
            "max_ratio": float(max(x["max_ratio"] for x in c)),
            "stuck": float(np.mean([x["stuck"] for x in c])),
            "mean_belt_speed": float(r["belt.belt_velocity"][whole].mean()),
            "mean_shaft_torque": float(r["belt.shaft_torque"][whole].mean()),
            "seconds": seconds}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=pathlib.Path, default=HERE.parent / "output")
    parser.add_argument("--stop", type=float, default=STOP)
    args = parser.parse_args()
    args.results.mkdir(parents=True, exist_ok=True)
    rows, traces = [], {}
    for ladder, values in LADDERS.items():
        for value in values:
            setting = {**BASE, ladder: value}
            r, seconds = run(**setting, stop=args.stop)
            rows.append({"ladder": ladder, **summary(r, seconds, **setting)})
            if setting == BASE or (ladder == "step" and value == min(values)):
                traces[f"{setting['step']:g}"] = r
            print(rows[-1])
    (args.results / "stick_slip.json").write_text(json.dumps(
        {"law": LAW, "belt": BELT, "stop": args.stop, "rows": rows}, indent=1))

    lines = [f"Stick-slip limit cycle of the belt drive (law {LAW}, belt {BELT}; cycles after "
             f"the first two of {args.stop:g} s; mean ± standard deviation over the cycles):", "",
             "| ladder | coupling step [s] | internal step [s] | nx | cycles | period [ms] "
             "| peak belt speed [m/s] | stuck per cycle [ms] | max T/N | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['ladder']} | {r['step']:g} | {r['internal_step']:g} | {r['nx']} "
                     f"| {r['cycles']} | {1e3 * r['period']:.2f} ± {1e3 * r['period_std']:.2f} "
                     f"| {r['peak']:.3f} ± {r['peak_std']:.3f} | {1e3 * r['stuck']:.1f} "
                     f"| {r['max_ratio']:.3f} | {r['seconds']:.1f} |")
    table = "\n".join(lines)
    (args.results / "stick_slip.md").write_text(table + "\n")
    print(table)

    fig, ax = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    for label, r in traces.items():
        ax[0].plot(r["time"] * 1e3, r["belt.belt_velocity"], lw=0.8,
                   label=f"coupling step {label} s")
        ax[1].plot(r["time"] * 1e3, r["body.friction_force"] / np.maximum(r["body.normal_force"],
                                                                           1e-300), lw=0.8)
    ax[0].axhline(DRIVE_SPEED, color="k", lw=0.5, ls=":")
    ax[0].set(ylabel="belt speed [m/s]")
    ax[0].legend(fontsize=8)
    ax[1].set(ylabel="T / N", xlabel="t [ms]", ylim=(-0.1, 0.7))
    fig.suptitle("Stick–slip of the belt under the body (Stribeck F_s = 0.6 → F_d = 0.3)")
    fig.tight_layout()
    fig.savefig(args.results / "stick_slip.png", dpi=110)
    print(f"\nwrote {args.results / 'stick_slip.png'}")


if __name__ == "__main__":
    main()
