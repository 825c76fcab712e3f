"""What a slip-rate law costs against the constant law on the same scene: the outside checks'
slowest scene (variant 3, a 28 x 19 stiff narrow body, N up to 5e7 N/m, the foundation speed
one sine period of amplitude 19.88 m/s, the top pressed then lifted), with the full law, the
Stribeck term only, the viscous term only, and the constant law. Each run is a child process
timed by its own CPU clock, REPEATS times; the table quotes the fastest of each and their
ratios to the constant law, measured in this one run (docs/contract.md, "Friction that
depends on the slip rate", quotes it).

The outside report gave the scene's parameters but not its top displacement: here it goes
linearly from -2.67e-5 m (pressed, the default scaled to the height) to +2e-5 m. On that
scene the FMU before the change took 143 s with the full law (16,810 substep halvings,
15,920 factorizations) against 0.9 s with the constant law.

With --before FMU the same runs are made, interleaved, with another build of the FMU (for
example one built at an earlier commit), and the table gives both.

    .venv/bin/python benchmarks/rate_law_cost.py [--repeats 3] [--fmu FMU] [--before FMU] [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import child  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]

STOP, STEP, PERIOD = 0.0097, 8.05e-4, 0.0097
SCENE = {"mass_matrix": 3, "width": 0.0349, "height": 0.1068, "nx": 28, "ny": 19,
         "density": 4681.6, "mu": 1.4464e10, "lambda": 5.0383e10,
         "friction_coefficient": 0.19642, "static_friction_ratio": 2.3534,
         "stribeck_velocity": 0.11687, "viscous_friction": 0.033259, "internal_step": 8.917e-7,
         "initial_velocity_x": 1.494, "initial_velocity_y": -0.274}
LAWS = {
    "full law": {},
    "Stribeck only": {"viscous_friction": 0.0},
    "viscous only": {"stribeck_velocity": 0.0, "static_friction_ratio": 1.0},
    "constant": {"stribeck_velocity": 0.0, "static_friction_ratio": 1.0, "viscous_friction": 0.0},
}
OUTPUTS = ["energy", "normal_force", "substep_refinements", "contact_iterations",
           "gauss_seidel_sweeps"]


def run(law, fmu=None):
    """In this process: one run of the scene with `law`; its CPU time and statistics."""
    import time

    import numpy as np

    from contactbody.fmu import Model, Profile

    times = np.linspace(0, PERIOD, 41)
    inputs = {"foundation_velocity": Profile.of(
                  [[t, 19.88 * np.sin(2 * np.pi * t / PERIOD)] for t in times]),
              "top_displacement": Profile.of([[0, -2.5e-5 * SCENE["height"] / 0.1], [PERIOD, 2e-5]])}
    steps = int(np.ceil(STOP / STEP))
    with Model(fmu, name="rate_law_cost") as model:
        tic = time.process_time()
        rows, _ = model.run({**SCENE, **LAWS[law]}, steps * STEP, STEP, OUTPUTS, inputs=inputs)
        cpu = time.process_time() - tic
        warnings = [m[2] for m in model.instance.messages if m[0] == 1]
    return {"law": law, "cpu_s": cpu, "halvings": int(rows["substep_refinements"].sum()),
            "newton_iterations": int(rows["contact_iterations"].sum()),
            "gauss_seidel_sweeps": int(rows["gauss_seidel_sweeps"].sum()),
            "max_normal_force": float(rows["normal_force"].max()),
            "halving_warnings": sum("substep halvings" in w for w in warnings)}


def in_child(law, fmu=None):
    return child.in_child("rate_law_cost", "run", law, fmu)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--fmu", type=pathlib.Path, help="this build's ContactBody.fmu (default: "
                        "contactbody.find_fmu())")
    parser.add_argument("--before", type=pathlib.Path, help="another build's ContactBody.fmu")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    builds = {"this build": str(args.fmu.resolve()) if args.fmu else None}
    if args.before:
        builds["before"] = str(args.before.resolve())
    results = {build: {} for build in builds}
    for _ in range(args.repeats):  # interleaved, so that a noisy stretch hits every law
        for law in LAWS:
            for build, fmu in builds.items():
                r = in_child(law, fmu)
                best = results[build].get(law)
                results[build][law] = r if best is None or r["cpu_s"] < best["cpu_s"] else best
                results[build][law].setdefault("all_cpu_s", []).append(r["cpu_s"])
    for laws in results.values():
        constant = laws["constant"]["cpu_s"]
        for r in laws.values():
            r["ratio_to_constant"] = r["cpu_s"] / constant
    args.out.mkdir(parents=True, exist_ok=True)
    # This build's laws at the top (what the docs quote), another build's under "before".
    record = dict(results["this build"])
    if args.before:
        record["before"] = {"fmu": str(args.before), **results["before"]}
    (args.out / "rate_law_cost.json").write_text(json.dumps(record, indent=1))
    lines = [f"The outside checks' slip-rate scene ({STOP:g} s in steps of {STEP:g} s; "
             "`benchmarks/rate_law_cost.py`), CPU seconds, fastest of "
             f"{args.repeats} runs each:", ""]
    if args.before:
        lines[-1:-1] = [f"`this build` is {args.fmu or 'build/ContactBody.fmu'}, `before` {args.before}."]
    lines += [("| build " if args.before else "") +
              "| law | CPU [s] | / constant law | halvings | Newton iterations | Gauss-Seidel sweeps "
              "| max normal force [N/m] | halving warnings |",
              ("|---" if args.before else "") + "|---|---|---|---|---|---|---|---|"]
    for build, laws in results.items():
        for law, r in laws.items():
            lines.append((f"| {build} " if args.before else "") +
                         f"| {law} | {r['cpu_s']:.2f} | {r['ratio_to_constant']:.1f} | {r['halvings']} "
                         f"| {r['newton_iterations']} | {r['gauss_seidel_sweeps']} "
                         f"| {r['max_normal_force']:.3g} | {r['halving_warnings']} |")
    lines += ["", "Newton iterations count 100 for a substep that Gauss-Seidel solved."]
    (args.out / "rate_law_cost.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
