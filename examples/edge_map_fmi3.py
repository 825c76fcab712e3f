"""The contact pressure x-t map straight from fmpy's simulate_fmu result of the FMI 3.0 FMU
(build/ContactBody_fmi3.fmu): its edge_* outputs are arrays of nx + 1 values, which fmpy
records as shaped columns, so no side file is needed. The scene is edge_history.py's
stick-slip (V = 0.05 m/s, F = 0.5, static friction twice the kinetic one, beta = 4e-6 s,
static preload, 20 ms). Writes OUT/edge_map_fmi3.png and prints what it checked.

    .venv/bin/python examples/edge_map_fmi3.py [--out DIR]
"""
import argparse

import numpy as np
from fmpy import simulate_fmu

from contactbody import edge
from scene import FMU, output_argument

FMU3 = FMU.with_name("ContactBody_fmi3.fmu")
SCENE = {"initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
         "static_friction_ratio": 2.0, "damping_stiffness": 4e-6, "internal_step": 2e-6}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    result = simulate_fmu(str(FMU3), stop_time=0.02, output_interval=2e-5, start_values=SCENE)
    print(f"edge_pressure recorded as {result['edge_pressure'].shape} (outputs x nodes)")
    e = edge.from_result(result)
    # The arrays are the scalar outputs resolved along the edge.
    dx = np.diff(e["x"][0])
    share = np.concatenate([[dx[0] / 2], (dx[:-1] + dx[1:]) / 2, [dx[-1] / 2]])
    error = np.abs(e["pressure"] @ share - result["normal_force"]).max()
    print(f"max |sum(share x pressure) - normal_force| = {error:.1e} N/m "
          f"(normal_force up to {result['normal_force'].max():.3e} N/m)")
    print("active nodes from edge_state equal active_contact_nodes at every output: "
          f"{np.array_equal((e['state'] > 0).sum(1), result['active_contact_nodes'])}")
    edge.plot(e, args.out / "edge_map_fmi3.png", times=[0.005, 0.0105, 0.0115, 0.015],
              title="FMI 3.0 arrays from simulate_fmu: stick-slip, V = 0.05 m/s, F = 0.5, "
                    "static friction x 2")
    print(f"wrote {args.out / 'edge_map_fmi3.png'}")


if __name__ == "__main__":
    main()
