"""Scenes beyond the paper (scenes issue, item 4), each through fmpy's simulate_fmu:

  impact:    body and plate (top_control = force, no top force) fall at 1 m/s onto the
             foundation from a 10 um gap, F = 0: energy before and after, contact intervals;
  lift-off:  static preload, then the top force goes from 15 kN/m (compression) to -5 kN/m
             (tension) and back, F = 0.3, damped: the contact opens and closes again;
  reversal:  foundation velocity 0.5 m/s -> -0.5 m/s, F = 0.3, damped, static preload: the
             friction force changes sign with it;
  stick-slip: slow foundation (V = 0.05 m/s), F = 0.5, static preload, beta = 4e-6 s (stable
             steady sliding), internal_step = 2e-6 s: Coulomb friction (static_friction_ratio
             = 1) against static friction twice the kinetic one (ratio 2): stick-slip cycles.

Writes OUT/scenes.png and OUT/scenes.json (the numbers docs/scenes.md and docs/user_guide.md
quote) and prints them.

    .venv/bin/python examples/scenes.py [--out DIR]
"""
import argparse
import json
import pathlib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from fmpy import simulate_fmu  # noqa: E402

from scene import FMU, OUT  # noqa: E402


def impact(variant, dt=4e-6, fmu=FMU):
    return simulate_fmu(str(fmu), stop_time=1.5e-3, output_interval=1e-5, start_values={
        "mass_matrix": variant, "internal_step": dt, "friction_coefficient": 0.0,
        "foundation_velocity": 0.0, "top_control": 1, "top_force": 0.0, "top_displacement": 0.0,
        "initial_gap": 1e-5, "initial_velocity_y": -1.0},
        output=["energy", "normal_force", "top_velocity"])


def contact_intervals(normal_force):
    """How many separate times the bottom is in contact: 1 for one clean impact; more when the
    contact force chatters (drops to zero and comes back) during the impact."""
    on = normal_force > 0
    return int(on[0]) + int(np.sum(on[1:] & ~on[:-1]))


VARIANT_NAMES = ["standard", "redistributed_normal", "redistributed_both",
                 "standard_implicit_contact", "redistributed_implicit_contact"]


def lift_off(fmu=FMU):
    """The plate starts at rest in static balance with 15 kN/m (initial_state = static); the
    top force ramps (input_interpolation = ramp) 15 -> -5 -> 15 kN/m over 0.02 s."""
    t = np.linspace(0, 0.02, 201)
    force = 15e3 - 20e3 * np.sin(np.pi * t / 0.02) ** 2
    signal = np.array(list(zip(t, force)), dtype=[("time", float), ("top_force", float)])
    return simulate_fmu(str(fmu), stop_time=0.02, output_interval=1e-4, input=signal,
                        start_values={"top_control": 1, "initial_state": 1,
                                      "top_force": 15e3, "friction_coefficient": 0.3,
                                      "foundation_velocity": 1.0, "damping_stiffness": 4e-6,
                                      "damping_mass": 200.0, "input_interpolation": 1},
                        output=["normal_force", "active_contact_nodes", "top_position",
                                "top_force"])


def reversal(fmu=FMU):
    t = np.linspace(0, 0.02, 201)
    velocity = np.where(t < 0.01, 0.5, -0.5)
    signal = np.array(list(zip(t, velocity)), dtype=[("time", float),
                                                     ("foundation_velocity", float)])
    return simulate_fmu(str(fmu), stop_time=0.02, output_interval=1e-4, input=signal,
                        start_values={"initial_state": 1, "friction_coefficient": 0.3,
                                      "damping_stiffness": 4e-6},
                        output=["friction_force", "normal_force", "slipping_contact_nodes",
                                "foundation_velocity"])


def stick_slip(static_friction_ratio, dt=2e-6, cells=20, stop_time=0.04, fmu=FMU):
    return simulate_fmu(str(fmu), stop_time=stop_time, output_interval=1e-5, start_values={
        "initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
        "static_friction_ratio": static_friction_ratio, "damping_stiffness": 4e-6,
        "internal_step": dt, "nx": cells, "ny": cells},
        output=["slipping_contact_nodes", "active_contact_nodes", "friction_force",
                "normal_force"])


def stick_slip_cycles(r, low=0.5, high=0.75, after=3e-3):
    """Times at which the bottom edge sticks again: the slipping share of its active nodes
    falls to `low` or below (most of the edge sticks) after having been at `high` or above
    (most of it slipped). The first 3 ms (the shear building up from rest) are left out."""
    share = r["slipping_contact_nodes"] / np.maximum(r["active_contact_nodes"], 1)
    times, slipped = [], False
    for t, sh in zip(r["time"], share):
        if t < after:
            continue
        if sh >= high:
            slipped = True
        elif sh <= low and slipped:
            times.append(t)
            slipped = False
    return np.array(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=OUT)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    results = {"impact": []}

    ax = axes[0, 0]
    for variant, name in enumerate(VARIANT_NAMES):
        for dt in (4e-6, 1e-6):
            r = impact(variant, dt)
            ratio = float(r["energy"][-1] / r["energy"][0])
            results["impact"].append({"mass_matrix": name, "dt": dt, "energy_ratio": ratio,
                                      "contact_intervals": contact_intervals(r["normal_force"])})
            print(f"impact {name}, dt = {dt:g}: E(end)/E(0) = {ratio:.4f}, "
                  f"{results['impact'][-1]['contact_intervals']} contact intervals")
            if dt == 4e-6 and variant in (0, 1, 4):
                ax.plot(r["time"] * 1e3, r["normal_force"] / 1e3,
                        label=f"{name}: E(end)/E(0) = {ratio:.4f}")
    ax.set(title="impact at 1 m/s (F = 0)", xlabel="t [ms]", ylabel="normal force [kN/m]")
    ax.legend(fontsize=7)

    ax = axes[0, 1]
    r = lift_off()
    open_steps = r["active_contact_nodes"] == 0
    results["lift_off"] = {"open_outputs": int(open_steps.sum()), "outputs": len(r),
                           "opens_ms": float(r["time"][open_steps][0] * 1e3),
                           "closes_ms": float(r["time"][open_steps][-1] * 1e3),
                           "nodes_at_end": int(r["active_contact_nodes"][-1]),
                           "peak_normal_force": float(r["normal_force"].max())}
    print(f"lift-off: contact open for {open_steps.sum()} of {len(r)} outputs, from "
          f"t = {r['time'][open_steps][0] * 1e3:.1f} to {r['time'][open_steps][-1] * 1e3:.1f} ms;"
          f" at the end {r['active_contact_nodes'][-1]} nodes in contact; peak normal force "
          f"{r['normal_force'].max():.4g} N/m")
    ax.plot(r["time"] * 1e3, r["normal_force"] / 1e3, label="normal force [kN/m]")
    ax.plot(r["time"] * 1e3, r["top_force"] / 1e3, "--", label="top force [kN/m]")
    ax.set(title="lift-off and re-contact (force control)", xlabel="t [ms]")
    ax.legend(fontsize=7)

    ax = axes[1, 0]
    r = reversal()
    before, after = r["time"] < 0.0095, r["time"] > 0.012
    results["reversal"] = {"friction_before": float(r["friction_force"][before].mean()),
                           "friction_after": float(r["friction_force"][after].mean())}
    print(f"reversal: mean friction force {r['friction_force'][before].mean():.0f} N/m before, "
          f"{r['friction_force'][after].mean():.0f} N/m after the reversal")
    ax.plot(r["time"] * 1e3, r["friction_force"] / 1e3, label="friction force [kN/m]")
    ax.plot(r["time"] * 1e3, 0.3 * r["normal_force"] / 1e3, ":", label="0.3 x normal force")
    ax.set(title="foundation velocity 0.5 -> -0.5 m/s", xlabel="t [ms]")
    ax.legend(fontsize=7)

    ax = axes[1, 1]
    results["stick_slip"] = []
    for ratio in (1.0, 1.5, 2.0):
        r = stick_slip(ratio)
        c = stick_slip_cycles(r)
        periods = np.diff(c)
        results["stick_slip"].append({
            "static_friction_ratio": ratio, "cycles": len(c),
            "period_ms": float(periods.mean() * 1e3) if len(c) > 1 else None,
            "period_spread_ms": float(periods.std() * 1e3) if len(c) > 1 else None})
        period = f"period {periods.mean() * 1e3:.2f} ms" if len(c) > 1 else "no period"
        print(f"stick-slip static_friction_ratio = {ratio:g}: {len(c)} cycles, {period}")
        if ratio != 1.5:
            ax.plot(r["time"] * 1e3, r["slipping_contact_nodes"] / r["active_contact_nodes"],
                    lw=0.8, label=f"F_s/F = {ratio:g}: {len(c)} cycles, {period}")
    ax.set(title="V = 0.05 m/s, F = 0.5: slipping share of the contact",
           xlabel="t [ms]", ylim=(0, 1.05))
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.out / "scenes.png", dpi=100)
    (args.out / "scenes.json").write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
