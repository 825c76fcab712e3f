"""The energy balance of a body that leaves the foundation and travels far (an outside
check's 2D scene: 54 x 12 mm, nx = 23, ny = 34, force control, the plate pressed with
5.3e4 N/m, then pulled up with -3.6e3 N/m from t = 2e-4 s): the balance's largest residual
so far, |E - E(0) - works| over the scale max(E(0), |works|), against the distance
travelled, for the full body damped (beta = 5.1e-6 s, the outside scene) and undamped, and
the reduced body (modes = 20) damped. docs/decisions.md, "Far travel and the energy
balance", quotes it.

    .venv/bin/python benchmarks/far_travel_balance.py [--fmu FMU] [--stop 0.04] [--out benchmarks/results]
"""
import argparse
import json
import pathlib

import numpy as np

from contactbody.fmu import Model, Profile

ROOT = pathlib.Path(__file__).resolve().parents[1]
SCENE = dict(width=0.054, height=0.012, nx=23, ny=34, mu=7.5e10, density=104.0,
             friction_coefficient=0.647, internal_step=7.3e-7, top_control=1, top_mass=0.0175,
             max_energy_ratio=0, **{"lambda": 3.7e9})
WORKS = ["clamp_work", "normal_contact_work", "friction_work", "damping_work", "foundation_work"]


def residuals(fmu, stop, damping, modes=0):
    force = Profile.of([(0.0, 5.3e4), (1e-4, 5.3e4), (2e-4, -3.6e3), (stop, -3.6e3)])
    with Model(fmu) as model:
        r, _ = model.run({**SCENE, "damping_stiffness": damping, "modes": modes}, stop, 1e-4,
                         ["energy", "top_position"] + WORKS, inputs={"top_force": force})
    E = r["energy"]
    works = r["clamp_work"] + r["normal_contact_work"] + r["friction_work"] - r["damping_work"]
    scale = np.maximum.accumulate(np.maximum(abs(E[0]), np.max([np.abs(r[w]) for w in WORKS], axis=0)))
    residual = np.maximum.accumulate(np.abs(E - E[0] - works) / scale)
    rows = [{"time": float(r["time"][k]), "travel_m": float(r["top_position"][k]),
             "residual": float(residual[k])} for k in range(0, len(E), max(1, len(E) // 10))]
    return rows + [{"time": float(r["time"][-1]), "travel_m": float(r["top_position"][-1]),
                    "residual": float(residual[-1])}]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", default=str(ROOT / "build" / "ContactBody.fmu"))
    parser.add_argument("--stop", type=float, default=0.04)
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    args = parser.parse_args()
    results = {"damped": residuals(args.fmu, args.stop, 5.1e-6),
               "undamped": residuals(args.fmu, args.stop, 0.0),
               "reduced, damped": residuals(args.fmu, args.stop, 5.1e-6, modes=20)}
    out = pathlib.Path(args.out)
    (out / "far_travel_balance.json").write_text(json.dumps(results, indent=1) + "\n")
    lines = ["# The energy balance of a body travelling far (benchmarks/far_travel_balance.py)", "",
             "| body | travel (m) | residual / scale |", "|---|---|---|"]
    for name, rows in results.items():
        lines += [f"| {name} | {row['travel_m']:.3g} | {row['residual']:.2g} |" for row in rows[1:]]
    (out / "far_travel_balance.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
