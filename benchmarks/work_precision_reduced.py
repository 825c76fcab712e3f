"""Work against precision with the reduced body (`modes`), beside the full body, in one run:
the error of the displacement field (max over the outputs of ||u - u_ref||_L2 and
|u - u_ref|_H1, as benchmarks/work_precision.py) against the solver time, on three scenes of
the paper's body (redistributed_normal, 5.12 ms, outputs every 0.16 ms):
  compressed: F = 0, the top held at -2.5e-5 m;
  damped sliding: F = 0.3, V = 20 m/s, beta = 4e-6 s;
  impact: F = 0, the body falling at 1 m/s onto the foundation from a 10 um gap, the clamp
    following it for the first output interval (0.16 ms) and then holding (displacement
    control: the reduced body has no force control).
Meshes h = 1, 0.5, 0.25 cm at the Table 2 step; the reduced body with 10, 20, 40, 80 modes at
that step and 4x it. Reference: the full body at h = 0.125 cm, dt = 1e-6 s. The Pareto table:
for each target, the cheapest setting that reaches it, full or reduced.

    .venv/bin/python benchmarks/work_precision_reduced.py [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import shutil
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
from convergence import errors, reference_fields  # noqa: E402
from scene import FMU, cells  # noqa: E402

from contactbody.fmu import Model, Profile  # noqa: E402

STOP, INTERVAL = 5.12e-3, 1.6e-4
REFERENCE = (1.25e-3, 1e-6)
MESHES = [(1e-2, 8e-6), (5e-3, 4e-6), (2.5e-3, 2e-6)]
MODES, FACTORS = (10, 20, 40, 80), (1, 4)
TARGETS = [3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8]
SCENES = {
    "compressed, F = 0": ({"friction_coefficient": 0.0}, None),
    "damped sliding, F = 0.3, beta = 4e-6 s": (
        {"friction_coefficient": 0.3, "damping_stiffness": 4e-6}, None),
    "impact at 1 m/s, F = 0": (
        {"friction_coefficient": 0.0, "foundation_velocity": 0.0, "top_displacement": 0.0,
         "initial_gap": 1e-5, "initial_velocity_y": -1.0},
        {"top_displacement": Profile.of([(0.0, 0.0), (INTERVAL, -INTERVAL), (STOP, -INTERVAL)])}),
}


def finite_modes(n):
    """redistributed_normal: free dofs less the edge's massless normal dofs."""
    return 2 * (n + 1) * n - (n + 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    model = Model(FMU, name="work_precision_reduced")

    def run(values, inputs, directory=None):
        if directory:
            values = {**values, "field_output_interval": INTERVAL,
                      "result_directory": str(directory)}
        return model.run(values, STOP, INTERVAL, [], inputs=inputs)[1]

    rows, references = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for scene, (values, inputs) in SCENES.items():
            n = cells(REFERENCE[0])
            ref_dir = tmp / "reference"
            shutil.rmtree(ref_dir, ignore_errors=True)
            references[scene] = run({**values, "nx": n, "ny": n, "internal_step": REFERENCE[1]},
                                    inputs, ref_dir)
            ref_fields = reference_fields(ref_dir)
            for h, dt in MESHES:
                n = cells(h)
                settings = [(0, dt)] + [(m, dt * f) for m in MODES if m <= finite_modes(n)
                                        for f in FACTORS]
                for modes, step in settings:
                    setting = {**values, "nx": n, "ny": n, "internal_step": step, "modes": modes}
                    run_dir = tmp / "run"
                    shutil.rmtree(run_dir, ignore_errors=True)
                    run(setting, inputs, run_dir)
                    l2, h1 = errors(ref_fields, run_dir, n)
                    rows.append({"scene": scene, "h": h, "dt": step, "modes": modes,
                                 "time": run(setting, inputs), "l2": l2, "h1": h1})
                    print(json.dumps(rows[-1]), flush=True)
    model.close()

    lines = ["# Work against precision: the reduced body", "",
             f"`benchmarks/work_precision_reduced.py`, one run: solver time (fmi2DoStep calls of "
             f"one warm instance over {STOP * 1e3:g} ms) against the displacement error (max over "
             f"{round(STOP / INTERVAL)} outputs of the L2 norm [m^2] and the H1 seminorm [m]) "
             f"against the full body at h = {REFERENCE[0] * 100:g} cm, dt = {REFERENCE[1]:g} s; "
             "modes 0 is the full body.", ""]
    for scene in SCENES:
        sel = [r for r in rows if r["scene"] == scene]
        lines += [f"## {scene}", "", "| h [cm] | modes | dt [s] | time [s] | L2 | H1 |",
                  "|---|---|---|---|---|---|"]
        lines += [f"| {r['h'] * 100:g} | {r['modes'] or 'full'} | {r['dt']:g} | {r['time']:.3g} | "
                  f"{r['l2']:.2e} | {r['h1']:.2e} |" for r in sel]
        lines += ["", "Cheapest setting per L2 target:", "",
                  "| L2 target | setting | time [s] | against the cheapest full body |",
                  "|---|---|---|---|"]
        for target in TARGETS:
            ok = [r for r in sel if r["l2"] <= target]
            full = [r for r in ok if r["modes"] == 0]
            if not ok:
                lines.append(f"| {target:g} | none reaches it | | |")
                continue
            best = min(ok, key=lambda r: r["time"])
            versus = (f"{min(full, key=lambda r: r['time'])['time'] / best['time']:.1f} x faster"
                      if full else "no full-body setting reaches it")
            lines.append(f"| {target:g} | h = {best['h'] * 100:g} cm, "
                         f"{'full' if not best['modes'] else str(best['modes']) + ' modes'}, "
                         f"dt = {best['dt']:g} | {best['time']:.3g} | {versus} |")
        lines.append("")
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "work_precision_reduced.json").write_text(
        json.dumps({"references": references, "rows": rows}, indent=1))
    (args.out / "work_precision_reduced.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
