"""One midpoint step of section 6's one-triangle example with friction that
weakens with the slip rate, F(v) = F_d + (F_s - F_d) exp(-|v| / v_s), v = slip / (dt / 2):
how many solutions the step has, over (dt, F_s - F_d, v_s), with the tangential mass kept
(redistributed_normal: m1 = 0, m2 = 1) or removed too (redistributed_both: m1 = m2 = 0).

For each parameter point build/elementary_maps solves the step on a grid of loads
f = (f_nu, f_tau) two ways: every solution directly (ElementaryExample::rate_solutions: open,
stick, and each root of the slip equation G_s(w) = 0 along the contact), and the contact
solver (ContactSolver, the FMU's, Newton from 28 starting multipliers).

The uniqueness condition (derived in docs/slip_rate_friction.md, "Friction that weakens with the slip
rate: one step"), for a load with sticking pressure N0 = b u_tau^k + f_nu >= 0, tau = dt / 2:
  C-: c - b F_s - (F_s - F_d) N0 / (v_s tau) > 0
  C+: c + b F_d - (F_s - F_d) M  / (v_s tau) > 0,  M = max_{w >= max(0, -N0/b)} N(w) exp(-w / (tau v_s))
(the slip equation is then increasing on each side of w = 0, and the step has one solution).
For N0 < 0 only C+ applies. The script checks that every load where it holds has exactly one
solution, by both counts. Writes OUT/stribeck_one_step.png and .json, prints a table.

    .venv/bin/python examples/stribeck_one_step.py [--points N] [--out DIR]
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

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "elementary_maps"
OUT = ROOT / "examples" / "output"
LAME, MU, MASS, U_TAU_OLD = 2.0, 1.0, 1.0, 0.1  # section 6's example (figures_3_5.py)
BOX = (-2.0, 2.0, -4.0, 4.0)
F_D = 0.5  # F_s = F_d + drop stays below c/b = 1.67 of the massless case: C- at rest holds
MASSES = [("redistributed_normal", 0.0, MASS), ("redistributed_both", 0.0, 0.0)]
DTS = [1.0, 0.3, 0.1, 0.03, 0.01, 0.001]
DROPS = [0.25, 0.5, 1.0]
STRIBECK = [0.1, 1.0]


def condition(b, c, tau, drop, vs, fn):
    """The derived sufficient condition for one solution, per load (vectorized over f_nu)."""
    n0 = b * U_TAU_OLD + fn
    k = drop / (vs * tau)
    # M = max over w >= w0 of (N0 + b w) exp(-w / L), L = tau vs, w0 = max(0, -N0 / b)
    L = tau * vs
    w0 = np.maximum(0.0, -n0 / b)
    w_star = np.maximum(w0, L - n0 / b)  # the maximizer, clipped to the branch
    M = (n0 + b * w_star) * np.exp(-w_star / L)
    c_plus = c + b * F_D - k * M > 0
    c_minus = np.where(n0 >= 0, c - b * (F_D + drop) - k * np.maximum(n0, 0) > 0, True)
    return c_plus & c_minus


def run(m1, m2, dt, drop, vs, points, directory):
    csv = pathlib.Path(directory) / "map.csv"
    line = subprocess.run(
        [str(PROGRAM), *map(repr, (LAME, MU, dt, m1, m2, F_D, U_TAU_OLD, *BOX)), str(points),
         str(csv), repr(drop), repr(vs), "0"], check=True, capture_output=True, text=True).stdout
    stats = json.loads(line)
    data = np.genfromtxt(csv, delimiter=",", names=True)
    holds = condition(stats["b"], stats["c"], dt / 2, drop, vs, data["f_nu"])
    exact, found = data["closed_count"].astype(int), data["found_count"].astype(int)
    return {
        "dt": dt, "drop": drop, "stribeck_velocity": vs, "c": stats["c"], "b": stats["b"],
        "loads": int(len(data)),
        "max_solutions": int(exact.max()),
        "loads_with_several": int((exact > 1).sum()),
        "solver_found_several": int((found > 1).sum()),
        "condition_holds": int(holds.sum()),
        "condition_holds_everywhere": bool(holds.all()),
        # the check: where the condition holds, exactly one solution, by both counts
        "violations_exact": int((holds & (exact != 1)).sum()),
        "violations_solver": int((holds & (found != 1)).sum()),
        "solver_agrees": int(stats["agree"]),
        "max_violation_of_23": stats["max_violation"],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=41, help="load grid points per axis")
    parser.add_argument("--out", type=pathlib.Path, default=OUT, help="output directory")
    parser.add_argument("--quick", action="store_true", help="a reduced grid (the test's)")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    dts, drops, stribeck = ([1.0, 0.1, 0.01], [0.5], [0.1]) if args.quick else (DTS, DROPS, STRIBECK)
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, m1, m2 in MASSES:
            results[name] = [run(m1, m2, dt, drop, vs, args.points, tmp)
                             for vs in stribeck for drop in drops for dt in dts]
    (args.out / "stribeck_one_step.json").write_text(json.dumps(results, indent=1))

    fig, axes = plt.subplots(len(stribeck), len(MASSES), figsize=(6 * len(MASSES), 3.6 * len(stribeck)),
                             squeeze=False)
    for col, (name, _, _) in enumerate(MASSES):
        for row, vs in enumerate(stribeck):
            ax = axes[row, col]
            grid = np.zeros((len(drops), len(dts)))
            unique = np.zeros_like(grid, dtype=bool)
            for r in results[name]:
                if r["stribeck_velocity"] == vs:
                    i, j = drops.index(r["drop"]), dts.index(r["dt"])
                    grid[i, j] = r["max_solutions"]
                    unique[i, j] = r["condition_holds_everywhere"]
            image = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis", vmin=1, vmax=3)
            for i in range(len(drops)):
                for j in range(len(dts)):
                    ax.text(j, i, f"{int(grid[i, j])}{'*' if unique[i, j] else ''}", ha="center",
                            va="center", color="w" if grid[i, j] < 2 else "k", fontsize=8)
            ax.set_xticks(range(len(dts)), [f"{d:g}" for d in dts])
            ax.set_yticks(range(len(drops)), [f"{d:g}" for d in drops])
            ax.set(xlabel="dt", ylabel="F_s - F_d", title=f"{name}, v_s = {vs:g}")
            fig.colorbar(image, ax=ax, label="most solutions over the loads")
    fig.suptitle(f"One step with velocity weakening (F_d = {F_D}): most solutions over "
                 f"{args.points}^2 loads; * = the derived condition holds at every load")
    fig.tight_layout()
    fig.savefig(args.out / "stribeck_one_step.png", dpi=100)

    print("| mass | v_s | F_s - F_d | dt | c | most solutions | loads with several (solver found several) "
          "| condition holds (loads) | violations exact / solver |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, rows in results.items():
        for r in rows:
            print(f"| {name} | {r['stribeck_velocity']:g} | {r['drop']:g} | {r['dt']:g} | {r['c']:.4g} | "
                  f"{r['max_solutions']} | {r['loads_with_several']} ({r['solver_found_several']}) | "
                  f"{r['condition_holds']} of {r['loads']} | {r['violations_exact']} / "
                  f"{r['violations_solver']} |")
    print(f"\nwrote {args.out / 'stribeck_one_step.png'}")


if __name__ == "__main__":
    main()
