"""Paper Figs. 3-5 (section 6): which closed form S1-S4 solves one midpoint step of the
one-triangle example, over the plane of loads f = (f_nu, f_tau), and how many solutions there
are; computed by the FMU's contact solver (ContactSolver, from 28 starting multipliers, through
build/elementary_maps) against the paper's closed forms.

Mass distributions, same material (lambda = 2 mu, as in Table 1), rho l^2/12 = 1, dt = 1:
  normal mass removed     (m1 = 0, m2 = 1)  F = 2.5 < c/b = 4.33   Fig. 3: one solution
  tangential mass removed (m1 = 1, m2 = 0)  F = 2.5 > c/b = 1.67   Fig. 4: three in sigma_4
  both removed            (m1 = 0, m2 = 0)  F = 2.5 > c/b = 1.67   as Fig. 4
  tangential removed      (m1 = 1, m2 = 0)  F = c/b = 1.67         Fig. 5: a segment on sigma_5
  normal mass removed, dt = 2 > dt_0 = 1.79 F = 2.5 > c/b = 2.33   as Fig. 4 (dt too long)

Writes examples/output/figures_3_5.png and figures_3_5.json and prints a table.

    .venv/bin/python examples/figures_3_5.py [--points N]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "elementary_maps"
OUT = ROOT / "examples" / "output"
LAME, MU, DT, MASS, U_TAU_OLD = 2.0, 1.0, 1.0, 1.0, 0.1
BOX = (-2.0, 2.0, -4.0, 4.0)  # f_nu and f_tau ranges
CRITICAL = (3 * MU + LAME) / (LAME + MU)  # c/b with m2 = 0: (l + 3 mu) / (l + mu)
# dt_0 of section 6: with m1 = 0, m2 > 0 the step is uniquely solvable for dt < dt_0.
DT0 = (4 * MASS / ((LAME + MU) / 2 * 2.5 - (LAME + 3 * MU) / 2)) ** 0.5
CASES = [  # (key, title, m1, m2, F, dt)
    ("normal", "normal mass removed (m1 = 0, m2 > 0), F < c/b", 0.0, MASS, 2.5, DT),
    ("tangential", "tangential mass removed (m1 > 0, m2 = 0), F > c/b", MASS, 0.0, 2.5, DT),
    ("both", "both removed (m1 = m2 = 0), F > c/b", 0.0, 0.0, 2.5, DT),
    ("critical", "tangential mass removed, F = c/b", MASS, 0.0, CRITICAL, DT),
    ("normal_long_step", f"normal mass removed, dt = 2 > dt_0 = {DT0:.2f}", 0.0, MASS, 2.5, 2.0),
]
# Region sets as bit masks (bit i = S_i): the colours of the maps.
CLASSES = [(1 << 1, "S1 (open)"), (1 << 2, "S2 (stick)"), (1 << 3, "S3 (slip +)"),
           (1 << 4, "S4 (slip -)"), ((1 << 1) | (1 << 2) | (1 << 4), "S1, S2 and S4"),
           (-1, "two solutions / segment S5")]
COLOURS = ["#d9d9d9", "#74add1", "#fdae61", "#a6d96a", "#d73027", "#542788"]


def run_case(m1, m2, friction, dt, points, directory):
    csv = pathlib.Path(directory) / "map.csv"
    line = subprocess.run(
        [str(PROGRAM), *map(repr, (LAME, MU, dt, m1, m2, friction, U_TAU_OLD, *BOX)),
         str(points), str(csv)], check=True, capture_output=True, text=True).stdout
    return json.loads(line), np.genfromtxt(csv, delimiter=",", names=True)


def class_index(mask, count, continuum):
    """Colour index of a grid point from its set of solution regions."""
    if continuum or count == 2:
        return len(CLASSES) - 1
    for k, (m, _) in enumerate(CLASSES[:-1]):
        if mask == m:
            return k
    raise ValueError(f"unexpected region set {mask}")


def image(data, mask_field, count_field, points):
    idx = [class_index(int(m), int(c), bool(s))
           for m, c, s in zip(data[mask_field], data[count_field], data["continuum"])]
    return np.array(idx).reshape(points, points).T  # rows: f_tau


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=201, help="grid points per axis")
    parser.add_argument("--out", type=pathlib.Path, default=OUT, help="output directory")
    args = parser.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    cmap = ListedColormap(COLOURS)
    fig, axes = plt.subplots(2, len(CASES), figsize=(4 * len(CASES), 8), sharex=True,
                             sharey=True)
    summary = {}
    with tempfile.TemporaryDirectory() as tmp:
        for col, (key, title, m1, m2, friction, dt) in enumerate(CASES):
            stats, data = run_case(m1, m2, friction, dt, args.points, tmp)
            disagree = data[(data["set_distance"] > 1e-6) | (
                (data["found_count"] != data["closed_count"]) & (data["continuum"] == 0))]
            stats["disagree_points"] = [[float(r["f_nu"]), float(r["f_tau"])] for r in disagree]
            # |c f_nu + b f_tau| of each disagreeing point: 0 up to rounding means on a boundary.
            stats["disagree_max_boundary_distance"] = float(max(
                (abs(stats["c"] * p[0] + stats["b"] * p[1]) for p in stats["disagree_points"]),
                default=0.0))
            stats["case"] = title
            stats["m1"], stats["m2"], stats["dt"] = m1, m2, dt
            summary[key] = stats
            for row, (mask, count, who) in enumerate(
                    [("closed_regions", "closed_count", "closed form"),
                     ("found_regions", "found_count", "contact solver, 28 starts")]):
                ax = axes[row, col]
                ax.imshow(image(data, mask, count, args.points), origin="lower", cmap=cmap,
                          vmin=-0.5, vmax=len(CLASSES) - 0.5, extent=BOX, aspect="auto",
                          interpolation="nearest")
                if row == 1 and len(disagree):
                    ax.plot(disagree["f_nu"], disagree["f_tau"], "kx", ms=5)
                if row == 1 and key == "critical":
                    cont = data[data["continuum"] == 1]
                    ax.plot(cont["f_nu"], cont["f_tau"], ".", color=COLOURS[-1], ms=4)
                ax.plot(-stats["b"] * U_TAU_OLD, stats["c"] * U_TAU_OLD, "k.", ms=4)
                ax.set_title(f"{title}\n{who}" if row == 0 else who, fontsize=9)
                if row == 1:
                    ax.set_xlabel("f_nu")
                if col == 0:
                    ax.set_ylabel("f_tau")
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in COLOURS]
    fig.legend(handles, [name for _, name in CLASSES], loc="lower center", ncol=len(CLASSES),
               fontsize=9)
    fig.suptitle("Section 6, Figs. 3-5: solution sets of one midpoint step "
                 f"(lambda = {LAME:g}, mu = {MU:g}, rho l^2/12 = {MASS:g}, "
                 f"u_tau^k = {U_TAU_OLD:g}; dt = {DT:g} unless stated)")
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    fig.savefig(out / "figures_3_5.png", dpi=100)
    (out / "figures_3_5.json").write_text(json.dumps(summary, indent=1))

    print("| case | dt | c/b | F | grid points | agree | 1 / 2 / 3 solutions | on sigma_5 | "
          "starts not converged | max violation of (23) | disagree |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for s in summary.values():
        print(f"| {s['case']} | {s['dt']:g} | {s['c_over_b']:.3f} | {s['friction']:.3f} | {s['points']} | "
              f"{s['agree']} | {s['one_solution']} / {s['two_solutions']} / "
              f"{s['three_solutions']} | {s['continuum_points']} | {s['failed_starts']} of "
              f"{28 * s['points']} | {s['max_violation']:.1e} | {len(s['disagree_points'])} "
              f"(max abs(c f_nu + b f_tau) = {s['disagree_max_boundary_distance']:.1e}) |")
    print(f"\nwrote {out / 'figures_3_5.png'}")


if __name__ == "__main__":
    main()
