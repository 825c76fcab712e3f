"""Linear stability of steady sliding on the paper scene: the largest growth rate of
the linearized semi-discrete problem about the state where every contact node is in contact and
slips (build/sliding_stability; the derivation is at the top of sliding_stability.cpp), for
F in {0, 0.2, 1.2} along the Table 2 mesh ladder.

Writes examples/output/sliding_stability.png and .json and prints a table.

    .venv/bin/python examples/sliding_stability.py [--finest NX]
"""
import argparse
import json
import pathlib
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "sliding_stability"
OUT = ROOT / "examples" / "output"
VARIANTS = {0: "standard", 1: "redistributed_normal", 2: "redistributed_both"}
HORIZON = 5e-3  # the convergence test's time span [s]


def analyse(nx, friction, variant):
    out = subprocess.run([str(PROGRAM), str(nx), repr(friction), str(variant)], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--finest", type=int, default=40, help="finest nx (dense eigenvalues)")
    parser.add_argument("--out", type=pathlib.Path, default=OUT)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    sizes = [n for n in (5, 10, 20, 40) if n <= args.finest]
    # Dense eigenvalues: nx = 40 (3239 dofs) takes about 2 min, so only for the FMU's default
    # variant and F > 0.
    rows = [analyse(nx, F, v) for v in VARIANTS for F in (0.0, 0.2, 1.2) for nx in sizes
            if nx <= 20 or (v == 1 and F > 0)]
    (args.out / "sliding_stability.json").write_text(json.dumps(rows, indent=1))

    print("| mass_matrix | F | h [cm] | dofs | growth rate [1/s] | its frequency [kHz] "
          "| growing modes | e-folds over 5 ms |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {VARIANTS[r['mass_matrix']]} | {r['friction']:g} | {r['h'] * 100:g} "
              f"| {r['dofs']} | {r['max_growth_rate']:.3g} | {r['frequency_hz'] / 1e3:.3g} "
              f"| {r['growing_modes']} | {r['max_growth_rate'] * HORIZON:.3g} |")

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for v, name in VARIANTS.items():
        for F, style in ((0.2, "--"), (1.2, "-")):
            pts = [(r["h"] * 100, r["max_growth_rate"]) for r in rows
                   if r["mass_matrix"] == v and r["friction"] == F]
            ax.loglog(*zip(*pts), style, marker="o", label=f"{name}, F = {F:g}")
    ax.set_xlabel("h [cm]")
    ax.set_ylabel("largest growth rate Re s [1/s]")
    ax.invert_xaxis()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Steady sliding, linearized: growth rate against mesh size (F = 0: none)")
    fig.tight_layout()
    fig.savefig(args.out / "sliding_stability.png", dpi=110)
    print(f"\nwrote {args.out / 'sliding_stability.png'}")


if __name__ == "__main__":
    main()
