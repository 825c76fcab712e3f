"""Does the stability map hold for the reduced body? The full body and the reduced body
(`modes` = 20 and 80) on the paper's body at nx = ny = 20, from the static start into sliding at
20 m/s, over a grid of F and beta: the growth rate of the kinetic energy's envelope over the
last half of 0.05 s (Re s = half the slope of log KE; > 0: the sliding grows away from the
steady state), and whether the FMU warned that the settings are in a measured unstable region
(the map, measured on the full body). The reduced body is judged against the full body's own
rate on the same mesh and step, in one run.

Writes benchmarks/results/reduced_stability.md and .json.

    .venv/bin/python benchmarks/reduced_stability.py [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import sys

import fmpy
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from contactbody.fmu import find_fmu  # noqa: E402

NX, STOP, H = 20, 0.05, 1e-4
FRICTIONS = (0.3, 0.5, 1.2)
BETAS = (0.0, 4e-6, 1e-5)
BODIES = (0, 20, 80)  # modes: 0 = the full body
WINDOW = 2e-3  # the envelope: the largest kinetic energy in each window


def growth_rate(time, kinetic):
    """Re s from the envelope of KE over the last half of the run (KE ~ exp(2 Re s t))."""
    late = time >= STOP / 2
    t, k = time[late], kinetic[late]
    edges = np.arange(t[0], t[-1] + 1e-12, WINDOW)
    centres, peaks = [], []
    for a, b in zip(edges[:-1], edges[1:]):
        inside = (t >= a) & (t < b)
        if inside.any() and k[inside].max() > 0:
            centres.append(t[inside][np.argmax(k[inside])])
            peaks.append(np.log(k[inside].max()))
    return float(np.polyfit(centres, peaks, 1)[0] / 2)


def run(friction, beta, modes):
    messages = []

    def logger(_env, _name, status, _category, message):
        messages.append(message.decode(errors="replace"))

    r = fmpy.simulate_fmu(str(find_fmu()), stop_time=STOP, output_interval=H, logger=logger,
                          start_values={"nx": NX, "ny": NX, "friction_coefficient": friction,
                                        "damping_stiffness": beta, "initial_state": 1,
                                        "modes": modes},
                          output=["kinetic_energy", "energy"])
    return {"friction": friction, "beta": beta, "modes": modes,
            "growth_rate": growth_rate(r["time"], r["kinetic_energy"]),
            "max_energy": float(r["energy"].max()),
            "warned_unstable": any("unstable region" in m for m in messages)}


def report(rows):
    lines = [f"# Stability of damped sliding: the reduced body against the full body (nx = {NX})",
             "", f"Growth rate Re s [1/s] of the kinetic energy's envelope over [{STOP / 2:g}, "
             f"{STOP:g}] s from the static start at 20 m/s; 'warns': the FMU's map warning.", "",
             "| F | beta [s] | full body | " + " | ".join(f"modes = {m}" for m in BODIES[1:])
             + " | warns |", "|---|---|---|" + "---|" * (len(BODIES) - 1) + "---|"]
    for f in FRICTIONS:
        for b in BETAS:
            cell = {r["modes"]: r for r in rows if r["friction"] == f and r["beta"] == b}
            lines.append(f"| {f:g} | {b:g} | " +
                         " | ".join(f"{round(cell[m]['growth_rate']):d}" for m in BODIES) +
                         f" | {'yes' if cell[0]['warned_unstable'] else 'no'} |")
    s = summarize(rows)
    lines += ["", f"Where the map does not warn, the largest rate of any body is "
              f"{s['largest_rate_unwarned']:.0f} /s. Where it warns, the reduced bodies' rate exceeds "
              f"the full body's by at most {s['largest_excess_of_reduced']:.0f} /s."]
    return "\n".join(lines) + "\n"


def summarize(rows):
    """What the table says about the map, for the reduced body."""
    full = {(r["friction"], r["beta"]): r for r in rows if r["modes"] == 0}
    return {
        "largest_rate_unwarned": max(r["growth_rate"] for r in rows
                                     if not full[r["friction"], r["beta"]]["warned_unstable"]),
        "largest_excess_of_reduced": max(
            r["growth_rate"] - full[r["friction"], r["beta"]]["growth_rate"] for r in rows
            if r["modes"] and full[r["friction"], r["beta"]]["warned_unstable"])}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    rows = [run(f, b, m) for f in FRICTIONS for b in BETAS for m in BODIES]
    summary = {"nx": NX, "stop_time": STOP, **summarize(rows), "rows": rows}
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "reduced_stability.json").write_text(json.dumps(summary, indent=1) + "\n")
    text = report(rows)
    (args.out / "reduced_stability.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
