"""A reduced body under a top_displacement that jumps (issue 53, item 3): the 10 x 10 rectangle,
damped (beta = 4e-6 s), F = 0.3, the foundation at rest, the top displacement switched between
-2.5e-5 and -3.5e-5 m at every communication point (0.1 ms) for 2 ms, held
(input_interpolation = hold) or ramped across each step (ramp); the clamp's work and the final
energy of the full body and of reduced bodies of 8, 20 and 80 modes.

Writes benchmarks/results/reduced_held_jumps.json and .md.

    .venv/bin/python benchmarks/reduced_held_jumps.py [--fmu FMU]
"""
import argparse
import json
import pathlib

import numpy as np

from contactbody import find_fmu
from contactbody.fmu import Model

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
STEP, STOP = 1e-4, 2e-3
LEVELS = (-2.5e-5, -3.5e-5)
MODES = [0, 8, 20, 80]
INTERPOLATION = {0: "hold", 1: "ramp"}


def run(fmu, modes, interpolation):
    with Model(fmu, name="jumps") as model:
        model.start({"modes": modes, "friction_coefficient": 0.3, "damping_stiffness": 4e-6,
                     "foundation_velocity": 0.0, "nx": 10, "ny": 10,
                     "input_interpolation": interpolation, "top_displacement": LEVELS[0]})
        inst = model.instance
        top, work, energy = (model.variable(n).valueReference
                             for n in ("top_displacement", "clamp_work", "energy"))
        steps = int(round(STOP / STEP))
        for k in range(steps):
            inst.setReal([top], [LEVELS[(k + 1) % 2]])
            inst.doStep(k * STEP, STEP)
        return {"modes": modes, "input_interpolation": INTERPOLATION[interpolation],
                "clamp_work": inst.getReal([work])[0], "energy": inst.getReal([energy])[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", type=pathlib.Path, default=None)
    args = parser.parse_args()
    fmu = str(find_fmu(args.fmu))
    rows = [run(fmu, m, i) for i in INTERPOLATION for m in MODES]
    OUT.mkdir(parents=True, exist_ok=True)
    record = {name: {str(r["modes"]): r for r in rows if r["input_interpolation"] == name}
              for name in INTERPOLATION.values()}
    (OUT / "reduced_held_jumps.json").write_text(json.dumps(record, indent=1))
    lines = ["# A reduced body under a top displacement that jumps", "",
             "`.venv/bin/python benchmarks/reduced_held_jumps.py`: the 10 x 10 rectangle, β = 4e-6 s, "
             "F = 0.3, the foundation at rest, the top switched between -2.5e-5 and -3.5e-5 m every "
             "0.1 ms for 2 ms (modes = 0: the full body).", "",
             "| input_interpolation | modes | clamp_work [J/m] | E(end) [J/m] |", "|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['input_interpolation']} | {r['modes']} | {r['clamp_work']:.3g} | {r['energy']:.3g} |")
    (OUT / "reduced_held_jumps.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
