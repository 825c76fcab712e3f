"""The bifurcation example's scene (stribeck_bifurcation.py: F_d = 0.5, F_s = 1.0, v_s = 0.1
m/s, foundation at 0.2 m/s, beta = 4e-6 s, static start) with redistributed_normal through
the FMU on finer meshes than the multi-start tool can afford: E(0.8 ms) along h, each mesh at
two time steps at or below the step from which its substeps are unique (2e-6 s at nx = 10,
5e-7 s at nx = 20, measured by stribeck_bifurcation.py; it scales with h^2, 2e-4 s / nx^2).
nx = 160 would need 4e-9 s, 2e5 substeps of 52,000 unknowns: not run.

Writes OUT/stribeck_mesh_ladder.{json,md}.

    .venv/bin/python examples/stribeck_mesh_ladder.py [--finest NX] [--out DIR]
"""
import argparse
import json
import pathlib
import time

import fmpy

ROOT = pathlib.Path(__file__).resolve().parents[1]
FMU = ROOT / "build" / "ContactBody.fmu"
SCENE = {"friction_coefficient": 0.5, "static_friction_ratio": 2.0, "stribeck_velocity": 0.1,
         "damping_stiffness": 4e-6, "initial_state": 1, "max_energy_ratio": 0.0,
         "foundation_velocity": 0.2, "top_displacement": -2.5e-5}
STOP = 8e-4
# Two steps per mesh, at and below its uniqueness threshold 2e-4 s / nx^2.
LADDER = [(10, 1e-6), (10, 5e-7), (20, 5e-7), (20, 2.5e-7), (40, 1.25e-7), (40, 6.25e-8),
          (80, 3.125e-8), (80, 1.5625e-8)]


def energy_at_stop(nx, dt):
    tic = time.perf_counter()
    r = fmpy.simulate_fmu(str(FMU), stop_time=STOP, output_interval=STOP / 8, output=["energy"],
                          start_values={**SCENE, "nx": nx, "ny": nx, "internal_step": dt})
    return {"nx": nx, "dt": dt, "energy": float(r["energy"][-1]),
            "seconds": time.perf_counter() - tic}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--finest", type=int, default=80)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "examples" / "output")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for nx, dt in LADDER:
        if nx <= args.finest:
            rows.append(energy_at_stop(nx, dt))
            print(rows[-1], flush=True)
    (args.out / "stribeck_mesh_ladder.json").write_text(json.dumps(rows, indent=1))
    lines = ["E(0.8 ms) [J/m], redistributed_normal, the bifurcation scene, through the FMU:", "",
             "| nx | h [cm] | dt [s] | E(0.8 ms) | change from the coarser mesh (finest dt) "
             "| wall [s] |", "|---|---|---|---|---|---|"]
    finest = {}
    for r in rows:
        finest[r["nx"]] = r  # the ladder lists each mesh's finer dt last
    previous = None
    for r in rows:
        change = ""
        if r is finest[r["nx"]] and previous is not None:
            change = f"{r['energy'] - previous['energy']:+.5f}"
        lines.append(f"| {r['nx']} | {10 / r['nx']:g} | {r['dt']:g} | {r['energy']:.6f} "
                     f"| {change} | {r['seconds']:.1f} |")
        if r is finest[r["nx"]]:
            previous = r
    table = "\n".join(lines)
    (args.out / "stribeck_mesh_ladder.md").write_text(table + "\n")
    print(table)


if __name__ == "__main__":
    main()
