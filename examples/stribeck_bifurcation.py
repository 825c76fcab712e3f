"""The bifurcation example in the full body. The paper's body, statically
preloaded (top at -25 um), on a foundation moving at V = 0.2 m/s, with velocity-weakening
friction F(v) = 0.5 + 0.5 exp(-|v| / 0.1 m/s) and beta = 4e-6 s, 0.8 ms, one substep per step.
build/stribeck_bifurcation solves every substep's contact problem again from 27 starting
multipliers and counts the distinct solutions; from the first substep with several, it runs
one trajectory per solution. For redistributed_normal and redistributed_both over a dt ladder
on two meshes. Writes OUT/stribeck_bifurcation.json and prints a table.

    .venv/bin/python examples/stribeck_bifurcation.py [--out DIR] [--quick]
"""
import argparse
import json
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "stribeck_bifurcation"
OUT = ROOT / "examples" / "output"
SCENE = {"F_d": 0.5, "ratio": 2.0, "v_s": 0.1, "V": 0.2, "beta": 4e-6}
DURATION = 8e-4
VARIANTS = {1: "redistributed_normal", 2: "redistributed_both"}
LADDER = {10: [4e-6, 2e-6, 1e-6, 5e-7, 2.5e-7], 20: [1e-6, 5e-7, 2.5e-7]}


def run(variant, nx, dt):
    steps = int(round(DURATION / dt))
    line = subprocess.run([str(PROGRAM), str(variant), str(nx), repr(dt), str(steps),
                           *(repr(SCENE[k]) for k in ("F_d", "ratio", "v_s", "V", "beta"))],
                          check=True, capture_output=True, text=True).stdout
    return json.loads(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=OUT, help="output directory")
    parser.add_argument("--quick", action="store_true", help="nx = 10 at 4e-6 and 1e-6 s only")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    ladder = {10: [4e-6, 1e-6]} if args.quick else LADDER
    results = [dict(run(v, nx, dt), variant=name)
               for v, name in VARIANTS.items() for nx, dts in ladder.items() for dt in dts]
    (args.out / "stribeck_bifurcation.json").write_text(json.dumps(results, indent=1))
    print("| variant | nx | dt [s] | substeps | with several solutions | most | E(0.8 ms) [J/m] "
          "| E(0.8 ms) of the branches from the first ambiguous substep |")
    print("|---|---|---|---|---|---|---|---|")
    for r in results:
        branches = ", ".join(f"{b['energy_end']:.5f}" + ("" if b["took_it"] else " (not taken)")
                             for b in r["branches"]) or "-"
        print(f"| {r['variant']} | {r['nx']} | {r['dt']:g} | {r['steps']} | "
              f"{r['substeps_with_several']} | {r['most_solutions']} | {r['energy_end']:.5f} | "
              f"{branches} |")


if __name__ == "__main__":
    main()
