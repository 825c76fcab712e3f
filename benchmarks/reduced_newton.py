"""Whether the 2D condensed contact solve's own Newton method pays: Newton on the reduced
system (the default, its LU reused and updated while the node states hold) against Newton on
the full generalized Jacobian, the method a 3D body's isotropic friction takes
(ContactSolverOptions::reduced_newton), on the same scenes in one run (bench_reduced_newton:
two simulations stepped in alternating rounds). Damped sliding from the static start with the
condensed solve forced: the full body at nx = 20, 40 and 160 and the reduced body at nx = 160
(80 modes), the foundation at 20 m/s (every active node slips) and at 0.01 m/s (nodes stick and
break loose), Coulomb friction and a slip-rate law. docs/decisions.md, "The 2D contact solve's
reduced Newton", quotes it.

Writes benchmarks/results/reduced_newton.{json,md}. About two minutes.

    .venv/bin/python benchmarks/reduced_newton.py [--build DIR] [--rounds 5]
"""
import argparse
import json
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"

# (body, nx, modes, dt, substeps a round, F, velocity, law): law None or (F_s / F_d, v_s).
SCENES = [
    ("full", 20, 0, 4e-6, 100, 0.3, 20.0, None),
    ("full", 20, 0, 4e-6, 100, 0.3, 0.01, None),
    ("full", 40, 0, 2e-6, 100, 0.3, 20.0, None),
    ("full", 40, 0, 2e-6, 100, 0.3, 0.01, None),
    ("full", 160, 0, 1e-6, 20, 0.3, 20.0, None),
    ("reduced", 160, 80, 2e-6, 100, 0.3, 20.0, None),
    ("reduced", 160, 80, 2e-6, 100, 0.3, 0.01, None),
    ("full", 40, 0, 2e-6, 100, 0.3, 20.0, (2.0, 5.0)),
    ("reduced", 160, 80, 2e-6, 100, 0.3, 20.0, (2.0, 5.0)),
]


def measure(build, scene, rounds):
    body, nx, modes, dt, steps, friction, velocity, law = scene
    command = [str(build / "bench_reduced_newton"), str(nx), str(modes), repr(dt), str(steps),
               str(rounds), repr(friction), repr(velocity)]
    if law:
        command += [repr(law[0]), repr(law[1])]
    result = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
    result["body"] = body
    result["law"] = "Coulomb" if law is None else f"Stribeck, F_s/F_d = {law[0]:g}, v_s = {law[1]:g} m/s"
    return result


def table(rows, rounds):
    lines = ["# The 2D contact solve: reduced Newton against the full Jacobian's", "",
             "`benchmarks/reduced_newton.py`: damped sliding from the static start, the condensed "
             f"solve forced, both methods stepped side by side in {rounds} alternating rounds "
             "(`bench_reduced_newton`). Per substep: the rounds' median wall µs, Newton "
             "iterations, Newton matrices factored (an LU of the reduced system, or of the full "
             "Jacobian's active rows); the outputs' largest difference between the two runs over "
             "all substeps, relative to the output's largest size. With a slip-rate law both "
             "methods take the full Jacobian (the reduced system eliminates a slipping node's "
             "tangential unknown, on which its friction then depends).", "",
             "| body | nx | Δt (s) | law | foundation (m/s) | contact nodes | active / slipping at the end | "
             "reduced µs | full Jacobian µs | full / reduced | iterations, reduced / full | "
             "factored, reduced / full | normal force diff | friction force diff | energy diff |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        a, b = r["methods"]["reduced"], r["methods"]["full_jacobian"]
        lines.append(
            f"| {r['body']} | {r['nx']} | {r['dt']:g} | {r['law']} | {r['velocity']:g} | "
            f"{r['contact_nodes']} | {a['active_nodes']} / {a['slipping_nodes']} | "
            f"{a['substep_us']:.0f} | {b['substep_us']:.0f} | {b['substep_us'] / a['substep_us']:.2f} | "
            f"{a['newton_iterations']:.2f} / {b['newton_iterations']:.2f} | "
            f"{a['factorizations']:.2f} / {b['factorizations']:.2f} | "
            f"{r['difference']['normal_force']:.1e} | {r['difference']['friction_force']:.1e} | "
            f"{r['difference']['energy']:.1e} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    rows = []
    for scene in SCENES:
        rows.append(measure(args.build, scene, args.rounds))
        print(json.dumps(rows[-1]), flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "reduced_newton.json").write_text(json.dumps({"rounds": args.rounds, "rows": rows}, indent=1))
    (OUT / "reduced_newton.md").write_text(table(rows, args.rounds))


if __name__ == "__main__":
    main()
