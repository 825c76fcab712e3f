"""Work against precision with substeps chosen by a tolerance, beside fixed substeps.

The paper's body (nx = ny = 20, redistributed_normal) over 2.56 ms, outputs every 0.16 ms:
  compressed: F = 0, the top held at -2.5e-5 m (the paper's initial state, undamped);
  damped sliding: F = 0.3, V = 20 m/s, beta = 4e-6 s;
  free body: the top a plate of 1 kg/m with no force on it (force control), falling at 1 m/s
  onto the foundation from 0.1 mm: it hits at 0.1 ms, leaves it at 0.52 ms and flies on,
  vibrating; and the same with beta = 4e-6 s, whose vibrations decay in flight;
  stick-slip: examples/scenes.py's (static start, F = 0.5, static friction twice it, V = 5 cm/s,
  beta = 4e-6 s) over 5.12 ms;
  2D mesh pad: the same law on examples/mesh_bodies.py's pad (Gmsh, 1 mm cells, two contact
  faces), the top held at -2e-5 m, over 5.12 ms.
Fixed substeps of 32 down to 1 us against `tolerance` from 1e-2 down (internal_step = the
communication step, so that the controller's sizes span it). Error: the largest difference of
the normal force, the friction force, the energy and the top's position over the outputs, each relative to its
largest value, against fixed substeps of 2.5e-7 s (a sixteenth of the finest fixed one and
below). Time: fmi2DoStep of one warm instance, best of 2; substeps: those that advanced the
state (the controller's estimates and rejected pairs cost more, counted as `solved`).

Writes benchmarks/results/substep_control.{json,md}.

    .venv/bin/python benchmarks/substep_control.py
"""
import json
import pathlib
import sys
import tempfile

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from contactbody import meshes  # noqa: E402
from contactbody.fmu import Model  # noqa: E402

OUT = ROOT / "benchmarks" / "results"
STOP, INTERVAL, REFERENCE = 2.56e-3, 1.6e-4, 2.5e-7
FREE = {"friction_coefficient": 0.0, "foundation_velocity": 0.0, "top_control": 1, "top_force": 0.0,
        "top_displacement": 0.0, "initial_gap": 1e-4, "initial_velocity_y": -1.0}
# examples/scenes.py's stick-slip (and examples/mesh_bodies.py's pad): from the static start.
STICK_SLIP = {"initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
              "static_friction_ratio": 2.0, "damping_stiffness": 4e-6}
SCENES = {  # the scene's values and its tolerances (1e-5 in sliding took 120 s: not run)
    "compressed, F = 0": ({"friction_coefficient": 0.0}, [1e-2, 1e-3, 1e-4, 1e-5]),
    "damped sliding, F = 0.3, beta = 4e-6 s": (
        {"friction_coefficient": 0.3, "damping_stiffness": 4e-6}, [1e-2, 1e-3, 1e-4]),
    "free body: falls, hits, flies off": (FREE, [1e-2, 1e-3, 1e-4]),
    "free body, damped: beta = 4e-6 s": (FREE | {"damping_stiffness": 4e-6}, [1e-2, 1e-3, 1e-4]),
    "stick-slip: static friction 2 F, V = 5 cm/s": (STICK_SLIP, [1e-2, 1e-3, 1e-4]),
    "2D mesh pad, stick-slip": (STICK_SLIP | {"top_displacement": -2e-5}, [1e-2, 1e-3, 1e-4]),
}
# Stick-slip cycles last 1.8 ms on the paper's body (examples/results/scenes.json): two of them.
STOPS = {"stick-slip: static friction 2 F, V = 5 cm/s": 5.12e-3, "2D mesh pad, stick-slip": 5.12e-3}
FIXED = [3.2e-5, 1.6e-5, 8e-6, 4e-6, 2e-6, 1e-6]
SERIES = ["normal_force", "friction_force", "energy", "top_position"]
READ = SERIES + ["substeps", "substep_refinements", "contact_iterations"]


def main():
    rows = []
    with Model() as m, tempfile.TemporaryDirectory() as folder:
        for scene, (values, tolerances) in SCENES.items():
            if scene.startswith("2D mesh pad"):
                values = values | {"mesh": str(meshes.pad(pathlib.Path(folder) / "pad.msh", size=1e-3))}
            stop = STOPS.get(scene, STOP)

            def run(values, stop=stop):
                best = None
                for _ in range(2):
                    s, seconds = m.run(values, stop, INTERVAL, READ)
                    best = seconds if best is None else min(best, seconds)
                return s, best

            ref, _ = m.run(values | {"internal_step": REFERENCE}, stop, INTERVAL, READ)

            def error(s):
                return max(float(np.max(np.abs(s[k] - ref[k])) / np.max(np.abs(ref[k])))
                           for k in SERIES if np.max(np.abs(ref[k])) > 0)

            settings = [("fixed", {"internal_step": dt}, dt) for dt in FIXED]
            settings += [("tolerance", {"internal_step": INTERVAL, "tolerance": tol}, tol)
                         for tol in tolerances]
            for kind, extra, value in settings:
                s, seconds = run(values | extra)
                row = {"scene": scene, "kind": kind, "value": value, "error": error(s),
                       "seconds": seconds, "substeps": int(s["substeps"].sum()),
                       "refinements": int(s["substep_refinements"].sum()),
                       "newton_iterations": int(s["contact_iterations"].sum())}
                rows.append(row)
                print(row, flush=True)
    for scene in SCENES:
        fixed = [r for r in rows if r["scene"] == scene and r["kind"] == "fixed"]
        for r in rows:
            if r["scene"] != scene or r["kind"] != "tolerance":
                continue
            r["error_over_tolerance"] = r["error"] / r["value"]
            # The cheapest fixed substep at least as accurate, and what it cost.
            better = [f for f in fixed if f["error"] <= r["error"]]
            cheapest = min(better, key=lambda f: f["seconds"]) if better else None
            r["fixed_at_equal_error"] = cheapest["value"] if cheapest else None
            r["over_fixed_at_equal_error"] = r["seconds"] / cheapest["seconds"] if cheapest else None
    OUT.mkdir(exist_ok=True)
    (OUT / "substep_control.json").write_text(json.dumps({"rows": rows}, indent=1) + "\n")
    lines = ["# Substeps chosen by a tolerance, against fixed substeps", "",
             "`.venv/bin/python benchmarks/substep_control.py`: " + __doc__.split("\n\n")[1].replace("\n", " "),
             "", "| scene | setting | error | time [s] | substeps advanced | refinements | Newton iterations "
             "| error / tolerance | fixed substep as accurate | time over it |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        what = f"fixed {r['value']:g} s" if r["kind"] == "fixed" else f"tolerance {r['value']:g}"
        ratio = f"{r['error_over_tolerance']:.2f}" if "error_over_tolerance" in r else ""
        fixed = (f"{r['fixed_at_equal_error']:g}" if r.get("fixed_at_equal_error") else
                 ("none" if r["kind"] == "tolerance" else ""))
        over = f"{r['over_fixed_at_equal_error']:.1f}" if r.get("over_fixed_at_equal_error") else ""
        lines.append(f"| {r['scene']} | {what} | {r['error']:.2e} | {r['seconds']:.3f} | {r['substeps']} | "
                     f"{r['refinements']} | {r['newton_iterations']} | {ratio} | {fixed} | {over} |")
    (OUT / "substep_control.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
