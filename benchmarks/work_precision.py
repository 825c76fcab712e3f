"""Work-precision benchmark: solver run time against error on scenes that
converge, for every mass_matrix variant, along the Table 2 ladder (h and dt halved together)
and along dt at h = 0.5 cm.

Scenes (the paper's body and material, 5.12 ms, outputs every 0.16 ms):
  compressed: F = 0, top held at -2.5e-5 m (the paper's initial state, undamped);
  damped sliding: F = 0.3, V = 20 m/s, Rayleigh damping beta = 4e-6 s (damped_stability.py:
    stable on every mesh of the ladder; convergence.py --damping-stiffness 4e-6 converges);
  impact: force-driven top (1 kg/m plate, no force), body and plate falling at 1 m/s onto the
    foundation from a 10 um gap, F = 0 (no GetFEM series: its script has no plate).
Time: one warm FMU instance (extracted and instantiated beforehand), fmi2DoStep calls only,
best of 3, no field output. Error: the maximum over the output times of ||u - u_ref||_L2 and
|u - u_ref|_H1, from a second run with field output, against one reference per scene
(redistributed_normal, h = 0.0625 cm, dt = 5e-7; the meshes nest, so u_h is exactly a fine
P1 field). The Pareto table gives, for each target error, the cheapest setting that reaches it.

GetFEM series: benchmarks/getfem_scene.py (python3-getfem) solves the same scenes with the
`standard` variant's discrete method from GetFEM's own assembly and contact brick; it matches
the FMU's `standard` run to round-off before the chaotic sliding separates them, and is timed
over its step loop alike. It runs on the coarser rungs only (h >= 0.5 cm, dt >= 8e-6): a
substep costs it milliseconds. The last table compares the cost per substep at equal settings.

Writes benchmarks/results/work_precision.{md,json,png}.

    .venv/bin/python benchmarks/work_precision.py [--quick]
"""
import argparse
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
from convergence import errors, reference_fields  # noqa: E402
from scene import DT_LADDER, FMU, TABLE2, cells  # noqa: E402

from contactbody.fmu import Model  # noqa: E402

OUT = ROOT / "benchmarks" / "results"
STOP, INTERVAL = 5.12e-3, 1.6e-4
REFERENCE = (6.25e-4, 5e-7)
VARIANTS = ["standard", "redistributed_normal", "redistributed_both",
            "standard_implicit_contact", "redistributed_implicit_contact"]
SCENES = {
    "compressed, F = 0": {"friction_coefficient": 0.0},
    "damped sliding, F = 0.3, beta = 4e-6 s": {"friction_coefficient": 0.3,
                                               "damping_stiffness": 4e-6},
    "impact at 1 m/s, F = 0": {"friction_coefficient": 0.0, "foundation_velocity": 0.0,
                               "top_control": 1, "top_force": 0.0, "top_displacement": 0.0,
                               "initial_gap": 1e-5, "initial_velocity_y": -1.0},
}
TARGETS = [3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8]


class WarmInstance:
    """One extracted FMU and one instance (reset between runs); each run times the doSteps."""

    def __init__(self, fmu=FMU):
        self.model = Model(fmu, name="work_precision")

    def run(self, values, result_directory=None):
        if result_directory:
            values = {**values, "field_output_interval": INTERVAL,
                      "result_directory": str(result_directory)}
        _, seconds = self.model.run(values, STOP, INTERVAL, [])
        return seconds


GETFEM_SCRIPT = ROOT / "benchmarks" / "getfem_scene.py"
GETFEM_PYTHON = "/usr/bin/python3"  # Debian's python3-getfem lives in the system interpreter


def getfem_run(n, dt, scene_values, directory):
    """Runs benchmarks/getfem_scene.py; returns (loop seconds, substeps, snapshots)."""
    out = directory / f"getfem_{n}_{dt:g}.npz"
    subprocess.run([GETFEM_PYTHON, str(GETFEM_SCRIPT), str(n), repr(dt), repr(STOP),
                    repr(INTERVAL), repr(scene_values.get("friction_coefficient", 0.0)),
                    repr(scene_values.get("damping_stiffness", 0.0)), str(out)],
                   check=True, capture_output=True, text=True)
    data = np.load(out)
    return (float(data["wall"]), int(data["substeps"]),
            [(t, None, u) for t, u in zip(data["times"], data["displacement"])])


def getfem_settings():
    """The rungs GetFEM runs: h >= 0.5 cm on the Table 2 ladder, dt >= 8e-6 on the dt ladder."""
    return [(ladder, h, dt) for ladder, h, dt in settings(quick=True)
            if (ladder == "Table 2 ladder" and h >= 5e-3) or dt >= 8e-6]


def settings(quick):
    """(ladder, h, dt) rungs; the Table 2 ladder gets one finer rung (0.125 cm, 1e-6 s)."""
    table2 = TABLE2 + ([] if quick else [(1.25e-3, 1e-6)])
    return ([("Table 2 ladder", h, dt) for h, dt in table2] +
            [("dt ladder, h = 0.5 cm", 5e-3, dt) for dt in DT_LADDER if dt != 4e-6])


def pareto(rows, key="l2"):
    """For each target, the cheapest row whose error reaches it."""
    out = []
    for target in TARGETS:
        ok = [r for r in rows if r[key] <= target]
        out.append((target, min(ok, key=lambda r: r["time"]) if ok else None))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="reference h = 0.125 cm, dt = 1e-6, no finer rung, one timing")
    args = parser.parse_args()
    OUT.mkdir(parents=True, exist_ok=True)
    fmu = WarmInstance()
    reference = (1.25e-3, 1e-6) if args.quick else REFERENCE
    repeats = 1 if args.quick else 3
    rows, references = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for scene, scene_values in SCENES.items():
            n = cells(reference[0])
            ref_dir = tmp / "reference"
            shutil.rmtree(ref_dir, ignore_errors=True)
            ref_values = {**scene_values, "nx": n, "ny": n, "internal_step": reference[1],
                          "mass_matrix": 1}
            references[scene] = {"h": reference[0], "dt": reference[1],
                                 "time": fmu.run(ref_values, ref_dir)}
            print(f"{scene}: reference {references[scene]['time']:.1f} s", flush=True)
            ref_fields = reference_fields(ref_dir)  # read once for all the runs
            for variant, name in enumerate(VARIANTS):
                for ladder, h, dt in settings(args.quick):
                    n = cells(h)
                    values = {**scene_values, "nx": n, "ny": n, "internal_step": dt,
                              "mass_matrix": variant}
                    run_dir = tmp / "run"
                    shutil.rmtree(run_dir, ignore_errors=True)
                    fmu.run(values, run_dir)
                    l2, h1 = errors(ref_fields, run_dir, n)
                    wall = min(fmu.run(values) for _ in range(repeats))
                    rows.append({"scene": scene, "variant": name, "ladder": ladder, "h": h,
                                 "dt": dt, "time": wall, "l2": l2, "h1": h1,
                                 "substeps": round(STOP / dt)})
                    print(json.dumps(rows[-1]), flush=True)
            for ladder, h, dt in (getfem_settings() if "top_control" not in scene_values else []):
                n = cells(h)
                wall, substeps, snaps = getfem_run(n, dt, scene_values, tmp)
                l2, h1 = errors(ref_fields, snaps, n)
                rows.append({"scene": scene, "variant": "GetFEM (standard)", "ladder": ladder,
                             "h": h, "dt": dt, "time": wall, "l2": l2, "h1": h1,
                             "substeps": substeps})
                print(json.dumps(rows[-1]), flush=True)

    lines = ["# Work against precision", "",
             f"Solver time: fmi2DoStep calls of one warm instance over {STOP * 1e3:g} ms, best of "
             f"{repeats}. Error: max over {round(STOP / INTERVAL)} outputs of ||u - u_ref||_L2 "
             "[m^2] and |u - u_ref|_H1 [m], reference redistributed_normal at "
             f"h = {reference[0] * 100:g} cm, dt = {reference[1]:g} s.",
             "Command: `.venv/bin/python benchmarks/work_precision.py`", ""]
    lines += ["## Cost per substep: GetFEM against the FMU, same method and settings", "",
              "| scene | h [cm] | dt [s] | FMU standard [us/substep] | GetFEM [ms/substep] "
              "| ratio | L2 FMU | L2 GetFEM |", "|---|---|---|---|---|---|---|---|"]
    for scene in SCENES:
        for g in (r for r in rows if r["scene"] == scene and r["variant"].startswith("GetFEM")):
            f = next((r for r in rows if r["scene"] == scene and r["variant"] == "standard"
                      and r["h"] == g["h"] and r["dt"] == g["dt"]), None)
            if f:
                per_f, per_g = f["time"] / f["substeps"], g["time"] / g["substeps"]
                lines.append(f"| {scene} | {g['h'] * 100:g} | {g['dt']:g} | {per_f * 1e6:.1f} "
                             f"| {per_g * 1e3:.2f} | {per_g / per_f:.0f} | {f['l2']:.2e} "
                             f"| {g['l2']:.2e} |")
    lines.append("")
    for scene in SCENES:
        sel = [r for r in rows if r["scene"] == scene]
        lines += [f"## {scene}", "", f"Reference run: {references[scene]['time']:.1f} s.", "",
                  "Cheapest setting for a target L2 error (Pareto front over all runs):", "",
                  "| target L2 [m^2] | mass_matrix | h [cm] | dt [s] | time [s] | L2 | H1 |",
                  "|---|---|---|---|---|---|---|"]
        for target, r in pareto(sel):
            lines.append(f"| {target:g} | " + (
                f"{r['variant']} | {r['h'] * 100:g} | {r['dt']:g} | {r['time']:.4f} "
                f"| {r['l2']:.2e} | {r['h1']:.2e} |" if r else "not reached | | | | | |"))
        lines += ["", "| mass_matrix | ladder | h [cm] | dt [s] | time [s] | L2 [m^2] | H1 [m] |",
                  "|---|---|---|---|---|---|---|"]
        for r in sel:
            lines.append(f"| {r['variant']} | {r['ladder']} | {r['h'] * 100:g} | {r['dt']:g} "
                         f"| {r['time']:.4f} | {r['l2']:.3e} | {r['h1']:.3e} |")
        lines.append("")
    (OUT / "work_precision.md").write_text("\n".join(lines) + "\n")
    (OUT / "work_precision.json").write_text(
        json.dumps({"references": references, "rows": rows}, indent=1))

    fig, axes = plt.subplots(1, len(SCENES), figsize=(6.5 * len(SCENES), 4.8))
    for ax, scene in zip(axes, SCENES):
        sel = [r for r in rows if r["scene"] == scene]
        for k, name in enumerate(VARIANTS + ["GetFEM (standard)"]):
            for ladder, style in (("Table 2 ladder", "o-"), ("dt ladder, h = 0.5 cm", "s--")):
                pts = sorted(((r["time"], r["l2"]) for r in sel
                              if r["variant"] == name and r["ladder"] == ladder))
                if pts:
                    ax.loglog(*zip(*pts), style, color=f"C{k}", ms=4,
                              label=f"{name}, {ladder}")
        front = [(r["time"], r["l2"]) for _, r in pareto(sel) if r]
        if front:
            ax.loglog(*zip(*sorted(set(front))), "k:", lw=2, label="cheapest for a target")
        ax.set_title(scene)
        ax.set_xlabel("solver time (doSteps of a warm instance) [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("max_t ||u - u_ref||_L2 [m²]")
    axes[-1].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(OUT / "work_precision.png", dpi=110)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
