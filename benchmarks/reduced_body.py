"""The reduced body against the full body (work-precision, first cut: the solver's
steppers, not yet through the FMU): the damped sliding scene (the paper's body, F = 0.3,
beta = 4e-6 s, 20 m/s, the top held, redistributed_normal) over 5 ms, at nx = 20, 40, 80
(and 160 with --fine), each mesh's usual step (4e-6 s x 20 / nx) and 4x it, for a ladder of
mode counts. Errors: L2 over the 1e-4 s communication steps of the step-averaged normal
force and of the energy, relative to the full body on the same mesh at its usual step.
Times: wall seconds per simulated second of both, measured in one run
(build/bench_reduced_body), and a reduced substep's cost pressed (a contact solve on every
node) against lifted off (none): what the contact solve costs.

    .venv/bin/python benchmarks/reduced_body.py [--fine] [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]
MODES = "20,40,80"
FACTORS = "1,4"


def run(nx, stop=0.005):
    dt = 4e-6 * 20 / nx
    out = subprocess.run([str(ROOT / "build" / "bench_reduced_body"), str(nx), repr(dt), repr(stop),
                          MODES, FACTORS], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def table(results):
    lines = ["The reduced body against the full body on the damped sliding scene, 5 ms "
             "(`benchmarks/reduced_body.py`; wall seconds per simulated second, both measured in "
             "one run; errors relative to the full body on the same mesh at its step):", "",
             "| nx | full [s/s] | modes | residual | dt [s] | reduced [s/s] | speed-up | "
             "normal force error | energy error | set-up [s] | substep pressed / lifted [µs] |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        for x in r["reduced"]:
            lines.append(f"| {r['nx']} | {r['full']['wall_per_simulated_s']:.3g} | {x['modes']} | "
                         f"{x['residual']} | {x['dt']:.3g} | {x['wall_per_simulated_s']:.3g} | "
                         f"{x['speedup']:.1f} | {x['error_normal_force']:.2e} | "
                         f"{x['error_energy']:.2e} | {x['setup_s']:.2f} | "
                         f"{x['substep_us_pressed']:.0f} / {x['substep_us_lifted']:.0f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fine", action="store_true", help="also nx = 160 (minutes)")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    results = [run(nx) for nx in ([20, 40, 80, 160] if args.fine else [20, 40, 80])]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "reduced_body.json").write_text(json.dumps(results, indent=1))
    (args.out / "reduced_body.md").write_text(table(results))
    print(table(results))


if __name__ == "__main__":
    main()
