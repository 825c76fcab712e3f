"""The contact edge over time: the stick-slip scene of scenes.py (V = 0.05 m/s, F = 0.5,
static friction twice the kinetic one, beta = 4e-6 s, static preload, 20 ms) with the edge
history on (edge_output_interval = 2e-5 s): x-t maps of the contact pressure and of the
stick/slip state, and pressure profiles. Writes OUT/edge_history.png, the history file
OUT/edge/contactbody_edge.npy and OUT/edge_history.json (what docs/scenes.md quotes); prints
what it shows.

    .venv/bin/python examples/edge_history.py [--out DIR]
"""
import argparse
import json

import numpy as np
from fmpy import simulate_fmu

from contactbody import edge
from scene import FMU, output_argument


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    args = parser.parse_args()
    directory = args.out / "edge"
    directory.mkdir(parents=True, exist_ok=True)
    simulate_fmu(str(FMU), stop_time=0.02, output_interval=2e-5, start_values={
        "initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
        "static_friction_ratio": 2.0, "damping_stiffness": 4e-6, "internal_step": 2e-6,
        "result_directory": str(directory), "field_output_interval": 0.02,
        "edge_output_interval": 2e-5}, output=["normal_force"])
    e = edge.load(directory / "contactbody_edge.npy")
    late = e["time"] > 0.003
    stick = (e["state"][late] == 1).mean(0)
    peak_node = np.unravel_index(e["pressure"].argmax(), e["pressure"].shape)[1]
    pressed = (e["pressure"][late] > 0).any(0)
    summary = {"records": len(e), "nodes": int(e["x"].shape[1]),
               "file_kB": (directory / "contactbody_edge.npy").stat().st_size / 1e3,
               "x_mm": (e["x"][0] * 1e3).tolist(), "stick_share_after_3ms": stick.tolist(),
               "peak_pressure_MPa": float(e["pressure"].max() / 1e6),
               "peak_x_mm": float(e["x"][0][peak_node] * 1e3),
               "last_pressed_x_mm": float(e["x"][0][np.nonzero(pressed)[0].max()] * 1e3)}
    (args.out / "edge_history.json").write_text(json.dumps(summary, indent=1) + "\n")
    print(f"{summary['records']} records of {summary['nodes']} nodes ({summary['file_kB']:.0f} kB)")
    print("share of the time each node sticks after 3 ms: " +
          " ".join(f"{s:.2f}" for s in stick))
    print(f"peak pressure {summary['peak_pressure_MPa']:.2f} MPa at x = "
          f"{summary['peak_x_mm']:.0f} mm; pressed after 3 ms up to x = "
          f"{summary['last_pressed_x_mm']:.0f} mm")
    edge.plot(e, args.out / "edge_history.png", times=[0.005, 0.0105, 0.0115, 0.015],
              title="stick-slip: V = 0.05 m/s, F = 0.5, static friction x 2")
    print(f"wrote {args.out / 'edge_history.png'}")


if __name__ == "__main__":
    main()
