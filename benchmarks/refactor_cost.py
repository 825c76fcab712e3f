"""A refactoring's cost: the substep's CPU time before and after it, in one interleaved run, and
whether the outputs are the same bits.

"Before" and "after" are two commits built alike (native Release, build_commit.py: a git
worktree in build-before/COMMIT/); each round runs every scene on both builds in turn, so that
a noisy machine slows both. A scene is a few communication steps after a warm-up step (the
factorization is not timed): 2D and 3D, condensed and sparse contact solves, the reduced body,
the slip-rate law.

    .venv/bin/python benchmarks/refactor_cost.py BEFORE AFTER [--rounds N] [--name NAME]

Writes benchmarks/results/NAME.json and NAME.md (NAME: refactor_cost).
"""
import argparse
import json
import math
import pathlib
import statistics
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from build_commit import build_commit  # noqa: E402
from contactbody import meshes  # noqa: E402
from contactbody.fmu import Model  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"
STEP = 1e-5


def scenes(mesh_dir):
    hemisphere = mesh_dir / "hemisphere.msh"
    pad = mesh_dir / "pad3d.msh"
    if not hemisphere.exists():
        meshes.hemisphere(hemisphere, radius=0.02, contact_size=1.5e-3, far_size=6e-3)
    if not pad.exists():
        meshes.pad3d(pad, size=4e-3)
    sliding3d = dict(friction_coefficient=0.3, foundation_velocity=2.0, foundation_velocity_z=1.0,
                     internal_step=2e-6)
    return {
        "2D nx = 80, sliding (condensed)": ("2", dict(nx=80, ny=40, friction_coefficient=0.3), 20),
        "2D nx = 160, ny = 8, sliding (sparse)": ("2", dict(nx=160, ny=8, friction_coefficient=0.3), 20),
        "2D nx = 80, reduced (40 modes)": ("2", dict(nx=80, ny=40, friction_coefficient=0.3, modes=40), 40),
        "2D nx = 40, slip-rate law": ("2", dict(nx=40, ny=20, friction_coefficient=0.3, static_friction_ratio=1.5,
                                                stribeck_velocity=0.5), 20),
        "3D hemisphere, sliding": ("3", dict(mesh=str(hemisphere), **sliding3d), 6),
        "3D pad, sliding (sparse)": ("3", dict(mesh=str(pad), **sliding3d), 6),
        "3D hemisphere, slip-rate law": ("3", dict(mesh=str(hemisphere), static_friction_ratio=1.5,
                                                   stribeck_velocity=0.2, **sliding3d), 6),
    }


def run(fmu, values, steps):
    """(CPU seconds per substep over `steps` steps after one warm-up step, the outputs' bits)."""
    with Model(fmu, name="cost") as model:
        model.start(values)
        inst = model.instance
        outputs = [v.valueReference for v in model.description.modelVariables
                   if v.causality == "output" and v.type == "Real"]
        top = model.variable("top_displacement").valueReference
        substeps = model.variable("substeps").valueReference
        inst.setReal([top], [-2e-5])
        inst.doStep(0, STEP)
        count, bits = 0, []
        start = time.process_time()
        for k in range(1, steps + 1):
            inst.setReal([top], [-2e-5 * (1 + 0.5 * math.sin(k / 3))])
            inst.doStep(k * STEP, STEP)
            count += inst.getInteger([substeps])[0]
            bits.append([float(x).hex() for x in inst.getReal(outputs)])
        return (time.process_time() - start) / count, bits


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--name", default="refactor_cost")
    args = parser.parse_args()
    commits = {label: subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", ref], check=True,
                                     capture_output=True, text=True).stdout.strip()
               for label, ref in (("before", args.before), ("after", args.after))}
    fmus = {}
    for label, commit in commits.items():
        build = build_commit(commit, ["ContactBody_fmu", "ContactBody3D_fmu"], ["-DCONTACTBODY_PORTABLE=OFF"])
        fmus[label] = {"2": build / "ContactBody.fmu", "3": build / "ContactBody3D.fmu"}
    mesh_dir = ROOT / "build-before" / "meshes"
    mesh_dir.mkdir(parents=True, exist_ok=True)
    table = scenes(mesh_dir)
    times = {name: {"before": [], "after": []} for name in table}
    same = {}
    for _ in range(args.rounds):
        for name, (model, values, steps) in table.items():
            bits = {}
            for label in ("before", "after"):
                seconds, bits[label] = run(fmus[label][model], values, steps)
                times[name][label].append(seconds)
            same[name] = same.get(name, True) and bits["before"] == bits["after"]
    rows = []
    for name, t in times.items():
        ratios = [a / b for a, b in zip(t["after"], t["before"])]
        rows.append({"scene": name, "before_us": 1e6 * statistics.median(t["before"]),
                     "after_us": 1e6 * statistics.median(t["after"]),
                     "ratio_median": statistics.median(ratios), "ratio_min": min(ratios),
                     "ratio_max": max(ratios), "same_bits": same[name]})
    result = {"before": commits["before"], "after": commits["after"], "rounds": args.rounds,
              "command": f".venv/bin/python benchmarks/refactor_cost.py {args.before} {args.after} "
                         f"--rounds {args.rounds} --name {args.name}", "scenes": rows}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / f"{args.name}.json").write_text(json.dumps(result, indent=1) + "\n")
    lines = [f"# Substep cost before ({commits['before']}) and after ({commits['after']})", "",
             f"`{result['command']}`: {args.rounds} interleaved rounds, CPU time per substep "
             "(median), and the ratio after / before per round (median, range).", "",
             "| scene | before (µs) | after (µs) | after / before | range | same bits |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['before_us']:.0f} | {r['after_us']:.0f} | {r['ratio_median']:.3f} "
                     f"| {r['ratio_min']:.3f}–{r['ratio_max']:.3f} | {'yes' if r['same_bits'] else 'no'} |")
    (RESULTS / f"{args.name}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
