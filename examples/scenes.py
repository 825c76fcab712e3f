"""Scenes beyond the paper (scenes issue, item 4), each through fmpy's simulate_fmu:

  impact:    body and plate (top_control = force, no top force) fall at 1 m/s onto the
             foundation from a 10 um gap, F = 0: energy before and after, contact intervals;
  lift-off:  static preload, then the top force goes from 15 kN/m (compression) to -5 kN/m
             (tension) and back, F = 0.3, damped: the contact opens and closes again;
  reversal:  foundation velocity 0.5 m/s -> -0.5 m/s, F = 0.3, damped, static preload: the
             friction force changes sign with it;
  stick-slip: slow foundation (V = 0.05 m/s), F = 0.5, static preload, with beta = 4e-6 s
             (stable sliding) and 1e-6 s (below the stable limit, 5.7e-6 s at F = 0.5).

Writes OUT/scenes.png and prints the measured numbers.

    .venv/bin/python examples/scenes.py [--out DIR]
"""
import argparse

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


def lift_off(fmu=FMU):
    """Force control from the static preload of the displacement-driven body is not available
    yet, so the plate starts at the paper's profile; the top force ramps (input_interpolation
    = ramp) 15 -> -5 -> 15 kN/m over 0.02 s."""
    t = np.linspace(0, 0.02, 201)
    force = 15e3 - 20e3 * np.sin(np.pi * t / 0.02) ** 2
    signal = np.array(list(zip(t, force)), dtype=[("time", float), ("top_force", float)])
    return simulate_fmu(str(fmu), stop_time=0.02, output_interval=1e-4, input=signal,
                        start_values={"top_control": 1, "friction_coefficient": 0.3,
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


def stick_slip(beta, fmu=FMU):
    return simulate_fmu(str(fmu), stop_time=0.02, output_interval=2e-5, start_values={
        "initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
        "damping_stiffness": beta}, output=["slipping_contact_nodes", "friction_force",
                                           "normal_force"])


def transitions(slipping, threshold=10):
    """Changes between mostly slipping (> threshold of 21 nodes) and not."""
    s = slipping > threshold
    return int(np.sum(s[1:] != s[:-1]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=OUT)
    args = parser.parse_args()
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))

    ax = axes[0, 0]
    for variant, name in ((0, "standard"), (1, "redistributed_normal"),
                          (4, "redistributed_implicit_contact")):
        r = impact(variant)
        ax.plot(r["time"] * 1e3, r["normal_force"] / 1e3, label=f"{name}: E(end)/E(0) = "
                f"{r['energy'][-1] / r['energy'][0]:.4f}")
        print(f"impact {name}: E(end)/E(0) = {r['energy'][-1] / r['energy'][0]:.4f}")
    ax.set(title="impact at 1 m/s (F = 0)", xlabel="t [ms]", ylabel="normal force [kN/m]")
    ax.legend(fontsize=7)

    ax = axes[0, 1]
    r = lift_off()
    open_steps = r["active_contact_nodes"] == 0
    print(f"lift-off: contact open for {open_steps.sum()} of {len(r)} outputs, from "
          f"t = {r['time'][open_steps][0] * 1e3:.1f} to {r['time'][open_steps][-1] * 1e3:.1f} ms;"
          f" at the end {r['active_contact_nodes'][-1]} nodes in contact")
    ax.plot(r["time"] * 1e3, r["normal_force"] / 1e3, label="normal force [kN/m]")
    ax.plot(r["time"] * 1e3, r["top_force"] / 1e3, "--", label="top force [kN/m]")
    ax.set(title="lift-off and re-contact (force control)", xlabel="t [ms]")
    ax.legend(fontsize=7)

    ax = axes[1, 0]
    r = reversal()
    before, after = r["time"] < 0.0095, r["time"] > 0.012
    print(f"reversal: mean friction force {r['friction_force'][before].mean():.0f} N/m before, "
          f"{r['friction_force'][after].mean():.0f} N/m after the reversal")
    ax.plot(r["time"] * 1e3, r["friction_force"] / 1e3, label="friction force [kN/m]")
    ax.plot(r["time"] * 1e3, 0.3 * r["normal_force"] / 1e3, ":", label="0.3 x normal force")
    ax.set(title="foundation velocity 0.5 -> -0.5 m/s", xlabel="t [ms]")
    ax.legend(fontsize=7)

    ax = axes[1, 1]
    for beta in (4e-6, 1e-6):
        r = stick_slip(beta)
        n = transitions(r["slipping_contact_nodes"])
        print(f"stick-slip beta = {beta:g} s: {n} stick/slip transitions")
        ax.plot(r["time"] * 1e3, r["slipping_contact_nodes"], label=f"β = {beta:g} s: {n} transitions")
    ax.set(title="V = 0.05 m/s, F = 0.5: slipping nodes (of 21)", xlabel="t [ms]")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{args.out}/scenes.png", dpi=100)


if __name__ == "__main__":
    main()
