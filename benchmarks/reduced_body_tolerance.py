"""The reduced body with substeps chosen by a tolerance, against its fixed substeps and the full
body, in one run: the scene of benchmarks/reduced_body_fmu.py (damped sliding from the static
start, 1e-4 s steps, 5 ms) at nx = 80 with 40 modes. The full body at that benchmark's step
(1e-6 s) is the reference; the reduced body at 1, 2, 4, ... times it up to the communication
step, and with `tolerance` 1e-2, 1e-3, 1e-4 (internal_step = the communication step). Errors:
L2 over the steps relative to the full body (reduced_body_fmu.py's); cost: CPU seconds per
simulated second, and over the cheapest fixed reduced run within 1 % of the full body.

    .venv/bin/python benchmarks/reduced_body_tolerance.py

Writes benchmarks/results/reduced_body_tolerance.{json,md}.
"""
import json
import pathlib
import sys
import tempfile

import fmpy

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))
from contactbody.fmu import find_fmu  # noqa: E402
from reduced_body_fmu import FACTORS, H, OUTPUTS, STOP, l2, run  # noqa: E402

NX, MODES, TOLERANCES = 80, 40, (1e-2, 1e-3, 1e-4)
OUT = ROOT / "benchmarks" / "results"


def main():
    fmu = find_fmu()
    md = fmpy.read_model_description(str(fmu))
    unzipped = tempfile.mkdtemp(prefix="reduced_body_tolerance_")
    fmpy.extract(str(fmu), unzipped)
    dt = 4e-6 * 20 / NX
    scene = dict(nx=NX, ny=NX, friction_coefficient=0.3, damping_stiffness=4e-6, internal_step=dt,
                 initial_state=1)
    _, (_, cpu_full), ref = run(md, unzipped, scene)
    settings = [("fixed", dt * f, {"internal_step": dt * f}) for f in FACTORS if dt * f <= H]
    settings += [("tolerance", tol, {"internal_step": H, "tolerance": tol}) for tol in TOLERANCES]
    rows = []
    for kind, value, extra in settings:
        _, (_, cpu), x = run(md, unzipped, scene | {"modes": MODES} | extra)
        row = {"kind": kind, "value": value, "cpu_per_simulated_s": cpu / STOP}
        for i, name in enumerate(OUTPUTS):
            row[f"error_{name}"] = l2(x[:, i], ref[:, i])
        row["error"] = max(row[f"error_{n}"] for n in OUTPUTS)
        rows.append(row)
        print(row, flush=True)
    within = [r for r in rows if r["kind"] == "fixed" and r["error"] <= 0.01]
    cheapest = min(within, key=lambda r: r["cpu_per_simulated_s"]) if within else None
    for r in rows:
        r["over_cheapest_fixed_within_1_percent"] = (
            r["cpu_per_simulated_s"] / cheapest["cpu_per_simulated_s"] if cheapest else None)
    result = {"nx": NX, "modes": MODES, "full_cpu_per_simulated_s": cpu_full / STOP,
              "cheapest_fixed_within_1_percent": cheapest["value"] if cheapest else None, "rows": rows}
    OUT.mkdir(exist_ok=True)
    (OUT / "reduced_body_tolerance.json").write_text(json.dumps(result, indent=1) + "\n")
    lines = ["# The reduced body with substeps chosen by a tolerance", "",
             "`.venv/bin/python benchmarks/reduced_body_tolerance.py`: " +
             __doc__.split("\n\n")[0].replace("\n", " "), "",
             f"The full body: {cpu_full / STOP:.3g} CPU s per simulated s.", "",
             "| reduced body, 40 modes | CPU s per simulated s | normal force error | friction force error "
             "| energy error | over the cheapest fixed within 1 % |", "|---|---|---|---|---|---|"]
    for r in rows:
        what = f"fixed {r['value']:g} s" if r["kind"] == "fixed" else f"tolerance {r['value']:g}"
        over = r["over_cheapest_fixed_within_1_percent"]
        lines.append(f"| {what} | {r['cpu_per_simulated_s']:.3g} | {r['error_normal_force']:.2e} | "
                     f"{r['error_friction_force']:.2e} | {r['error_energy']:.2e} | "
                     f"{'' if over is None else f'{over:.2f}'} |")
    (OUT / "reduced_body_tolerance.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
