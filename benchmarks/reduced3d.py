"""The reduced body of a 3D pad against the full body, error against the number of modes m
(issue 55). The pad is contactbody.meshes.pad3d (60 x 20 x 40 mm, chamfers and a slot, 4 mm
cells), pressed 0.1 mm by its clamp from the static start, under a foundation sliding at 1 m/s
whose heading turns from x to z between 0.2 and 1.0 ms (F = 0.5, damping_stiffness = 2e-6 s,
the default variant 1), to 1.2 ms, through ContactBody3D.fmu. For each edge (massless,
tangential_mass) and m, the largest difference over the run of the normal force and of the
friction force vector (x, z), relative to the full body's largest, the energy balance, and the
wall time of the run (basis included) against the full body's, measured in the same process.

Writes benchmarks/results/reduced3d.json and .md.

    .venv/bin/python benchmarks/reduced3d.py [--fmu build/ContactBody3D.fmu]
"""
import argparse
import json
import pathlib
import tempfile
import time

import fmpy
import numpy as np

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
SPEED, TURN, STOP, INTERVAL = 1.0, (2e-4, 1e-3), 1.2e-3, 2e-5
MODES = [20, 40, 80, 160, 320]
EDGES = {"massless": 1, "tangential_mass": 2}
OUTPUTS = ["normal_force", "friction_force", "friction_force_z", "energy", "clamp_work",
           "normal_contact_work", "friction_work", "damping_work", "foundation_work"]


def signals():
    times = np.array([0.0, TURN[0], TURN[1], STOP])
    heading = 0.5 * np.pi * np.clip((times - TURN[0]) / (TURN[1] - TURN[0]), 0, 1)
    return np.array(list(zip(times, SPEED * np.cos(heading), SPEED * np.sin(heading))),
                    dtype=[("time", float), ("foundation_velocity", float), ("foundation_velocity_z", float)])


def run(fmu, mesh, **values):
    started = time.perf_counter()
    r = fmpy.simulate_fmu(str(fmu), stop_time=STOP, output_interval=INTERVAL, input=signals(), output=OUTPUTS,
                          start_values={"mesh": str(mesh), "initial_state": 1, "top_displacement": -1e-4,
                                        "friction_coefficient": 0.5, "damping_stiffness": 2e-6,
                                        "input_interpolation": 1, "foundation_velocity": SPEED, **values})
    return r, time.perf_counter() - started


def balance(r):
    lhs = r["energy"] - r["energy"][0]
    rhs = r["clamp_work"] + r["normal_contact_work"] + r["friction_work"] - r["damping_work"]
    scale = max(r["energy"][0], *(np.abs(r[w]).max() for w in OUTPUTS[3:]))
    return float(np.abs(lhs - rhs).max() / scale)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", type=pathlib.Path, default=ROOT / "build" / "ContactBody3D.fmu")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        mesh = meshes.pad3d(pathlib.Path(tmp) / "pad3d.msh", size=4e-3)
        full, full_seconds = run(args.fmu, mesh)
        normal_scale = np.abs(full["normal_force"]).max()
        friction_scale = np.hypot(full["friction_force"], full["friction_force_z"]).max()
        rows = []
        for edge, code in EDGES.items():
            for m in MODES:
                r, seconds = run(args.fmu, mesh, modes=m, reduced_edge=code)
                rows.append({
                    "edge": edge, "modes": m,
                    "normal_force_error": float(np.abs(r["normal_force"] - full["normal_force"]).max() / normal_scale),
                    "friction_force_error": float(np.hypot(r["friction_force"] - full["friction_force"],
                                                           r["friction_force_z"] - full["friction_force_z"]).max()
                                                  / friction_scale),
                    "energy_balance": balance(r), "seconds": seconds, "speedup": full_seconds / seconds})
                print(rows[-1], flush=True)
    result = {"scene": {"mesh": "contactbody.meshes.pad3d(size=4e-3)", "speed_m_per_s": SPEED,
                        "turn_s": TURN, "stop_s": STOP, "friction_coefficient": 0.5},
              "full": {"seconds": full_seconds, "energy_balance": balance(full),
                       "largest_normal_force_N": float(normal_scale),
                       "largest_friction_force_N": float(friction_scale)},
              "rows": rows}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "reduced3d.json").write_text(json.dumps(result, indent=1) + "\n")
    lines = ["# The reduced 3D pad against the full body", "",
             "`.venv/bin/python benchmarks/reduced3d.py`: " + __doc__.split("\n\n")[0].replace("\n", " "), "",
             f"Full body: {full_seconds:.1f} s, energy balance {balance(full):.1e}, largest normal force "
             f"{normal_scale:.0f} N, largest friction force {friction_scale:.0f} N.", "",
             "| edge | m | normal force error | friction force error | energy balance | run [s] | speed-up |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['edge']} | {r['modes']} | {r['normal_force_error']:.2e} | "
                     f"{r['friction_force_error']:.2e} | {r['energy_balance']:.1e} | {r['seconds']:.2f} | "
                     f"{r['speedup']:.1f} |")
    (OUT / "reduced3d.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
