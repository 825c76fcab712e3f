"""Work-precision benchmark (issue 4): run time of fmpy.simulate_fmu against the error, for the
four mass_matrix variants, over the Table 2 ladder (h and dt halved together) and over dt at a
fixed mesh (h = 0.5 cm), for F = 0.2 and F = 1.2.

Error: the maximum over the output times of the L2(Omega) norm of u - u_ref, from the field
output, against a fine reference run of the same variant (h = 0.125 cm, dt = 1e-6). The horizon
is short (1.28 ms, 8 outputs) because steady sliding is unstable for F > 0 (examples/README.md):
later, no two discretizations stay close. Writes benchmarks/results/work_precision.{md,json,png}.

    .venv/bin/python benchmarks/work_precision.py
"""
import json
import pathlib
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
from convergence import errors  # noqa: E402
from scene import DT_LADDER, TABLE2, VARIANTS, cells, simulate  # noqa: E402

OUT = ROOT / "benchmarks" / "results"
STOP, INTERVAL = 1.28e-3, 1.6e-4
REFERENCE = (1.25e-3, 1e-6)


def run(directory, h, dt, variant, friction):
    n = cells(h)
    _, wall = simulate(STOP, INTERVAL, nx=n, ny=n, internal_step=dt, mass_matrix=variant,
                       friction_coefficient=friction, result_directory=str(directory),
                       field_output_interval=INTERVAL, outputs=["energy"])
    return wall


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for friction in (0.2, 1.2):
            for variant, name in enumerate(VARIANTS):
                ref = tmp / f"ref_{friction}_{variant}"
                run(ref, *REFERENCE, variant, friction)
                ladders = [("Table 2 ladder", h, dt) for h, dt in TABLE2] + \
                          [("dt ladder, h = 0.5 cm", 5e-3, dt) for dt in DT_LADDER]
                for ladder, h, dt in ladders:
                    d = tmp / f"run_{friction}_{variant}_{h}_{dt}"
                    wall = run(d, h, dt, variant, friction)
                    l2, h1 = errors(ref, d, cells(h))
                    rows.append({"friction": friction, "variant": name, "ladder": ladder, "h": h,
                                 "dt": dt, "wall": wall, "l2": l2, "h1": h1})
                    print(json.dumps(rows[-1]), flush=True)

    lines = ["# Work against precision (error: max over 8 outputs in [0, 1.28 ms] of ||u - u_ref||_L2,"
             " reference h = 0.125 cm, dt = 1e-6, same variant)", "",
             "| F | mass_matrix | ladder | h [cm] | dt [s] | run time [s] | L2 error [m^2] | H1 error [m] |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['friction']:g} | {r['variant']} | {r['ladder']} | {r['h'] * 100:g} "
                     f"| {r['dt']:g} | {r['wall']:.3f} | {r['l2']:.3e} | {r['h1']:.3e} |")
    (OUT / "work_precision.md").write_text("\n".join(lines) + "\n")
    (OUT / "work_precision.json").write_text(json.dumps(rows, indent=1))

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, friction in zip(axes, (0.2, 1.2)):
        for k, name in enumerate(VARIANTS):
            for ladder, style in (("Table 2 ladder", "o-"), ("dt ladder, h = 0.5 cm", "s--")):
                sel = [r for r in rows if r["friction"] == friction and r["variant"] == name
                       and r["ladder"] == ladder]
                ax.loglog([r["wall"] for r in sel], [r["l2"] for r in sel], style, color=f"C{k}",
                          label=f"{name}, {ladder}", ms=4)
        ax.set_title(f"F = {friction:g}")
        ax.set_xlabel("fmpy.simulate_fmu run time [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("max_t L2 error [m²]")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(OUT / "work_precision.png", dpi=110)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
