"""What a refined contact boundary costs (issue 54): a pad (contactbody.meshes.pad, 80 mm
wide, its two contact faces 66 mm together) whose cells along the contact faces shrink so that
it has about N contact nodes, growing away from them; damped sliding at 20 m/s (F = 0.3,
beta = 4e-6 s, 1e-6 s substeps) from the static start. Per N and body, in a process of its own
(build/bench_contact_scaling): the static start's wall time, one substep's (the mean over 300
substeps after the first step: sliding, past the start's changes of pattern), one sparse solve
of the same body (its floor, timed beside the substeps in the same process), the contact
solve's counts and the process's peak memory. Communication steps of 1e-5 s (10 substeps);
from --saved-min nodes on also with a state saved before each step, as an importer that can go
back a step does (what the contact solve keeps from step to step, GCR's directions above all,
goes where a state is saved, so that a restored one replays). Each case runs --repeat times, the cases in
turn, and a row gives the median of its runs' times (each run's are kept): this machine's speed
drifts by 2-4x between runs, and a doubling's ratio compares two processes. The counts must
agree between runs (the solve is deterministic). The full body as the FMU takes it (the cost
model's choice), the condensed contact solve it had before (up to --condensed-max nodes: it
took 356 ms a substep and 130 s to start at 1,586), the sparse solve with a slipping node's
friction left to GCR instead of its factor's slipping rows (from --gcr-min nodes: the sparse
solve as it was before those rows), and the reduced body (40 modes, up to --reduced-max:
2.5 GB at 1,586).

Writes benchmarks/results/contact_scaling.json and contact_scaling.md (--output names
others: `--substeps 1000 --output contact_scaling_long --condensed-max 0 --reduced-max 0
--gcr-min 100000` measures the full body's substep over 1,000 substeps, past the transient
that a longer contact edge still has at 300).

    .venv/bin/python benchmarks/contact_scaling.py [--counts 101 ... 3201] [--build DIR]
                                                   [--repeat 3] [--substeps 300] [--output NAME]
                                                   [--analyze-only]
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
CONTACT_LENGTH = 0.066  # m: the two contact faces of an 80 mm pad with 4 mm chamfers and a 6 mm slot
SCENE = {"initial_state": 1, "friction_coefficient": 0.3, "damping_stiffness": 4e-6,
         "internal_step": 1e-6, "foundation_velocity": 20.0, "top_displacement": -5e-6}
SUBSTEPS = 300
STEP = 1e-5  # s: the communication step
SAVED = "full, a state saved each step"
TIMES = ("static_start_seconds", "substep_seconds", "sparse_solve_seconds", "substep_per_solve")


def pad_mesh(folder, n):
    from contactbody import meshes
    return meshes.pad(pathlib.Path(folder) / f"pad_{n}.msh", width=0.08, size=2e-3,
                      contact_size=CONTACT_LENGTH / (n - 2))


def measure(build, mesh, modes, path, substeps=SUBSTEPS, friction=SCENE["friction_coefficient"],
            save=False):
    """One case in a process of its own: bench_contact_scaling's JSON."""
    out = subprocess.run([str(build / "bench_contact_scaling"), str(mesh), str(modes), path,
                          str(substeps), repr(friction), "2", repr(SCENE["top_displacement"]), "0",
                          repr(STEP), str(int(save))], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--counts", type=int, nargs="+", default=[101, 201, 401, 801, 1601, 3201])
    parser.add_argument("--condensed-max", type=int, default=801)
    parser.add_argument("--reduced-max", type=int, default=801)
    parser.add_argument("--gcr-min", type=int, default=401)
    parser.add_argument("--saved-min", type=int, default=401)
    parser.add_argument("--substeps", type=int, default=SUBSTEPS)
    parser.add_argument("--output", default="contact_scaling")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--analyze-only", action="store_true",
                        help="derive the ratios and tables again from the results file")
    args = parser.parse_args()
    if args.analyze_only:
        saved = json.loads((OUT / f"{args.output}.json").read_text())
        write(saved["rows"], saved["repeat"], saved["substeps"], args.output)
        return
    runs = {}
    with tempfile.TemporaryDirectory() as tmp:
        cases = []
        for n in args.counts:
            mesh = pad_mesh(tmp, n)
            cases.append((n, "full", mesh, 0, "automatic", False))
            if n >= args.gcr_min:
                cases.append((n, "full, slips by GCR", mesh, 0, "sparse_gcr", False))
            if n >= args.saved_min:
                cases.append((n, SAVED, mesh, 0, "automatic", True))
            if n <= args.condensed_max:
                cases.append((n, "full, condensed", mesh, 0, "condensed", False))
            if n <= args.reduced_max:
                cases.append((n, "reduced", mesh, 40, "automatic", False))
        for _ in range(args.repeat):
            for n, body, mesh, modes, path, save in cases:
                r = measure(args.build, mesh, modes, path, args.substeps, save=save)
                print(json.dumps({"requested": n, "body": body, **r}), flush=True)
                runs.setdefault((n, body), []).append(r)
    rows = []
    for (n, body), measured in runs.items():
        row = {"requested": n, "body": body, **measured[0]}
        for key, value in measured[0].items():
            if key not in TIMES and key != "peak_memory_mb" and any(m[key] != value for m in measured):
                raise SystemExit(f"{n} {body}: {key} differs between runs: {[m[key] for m in measured]}")
        for key in TIMES + ("peak_memory_mb",):
            row[key + "_runs"] = [m[key] for m in measured]
            row[key] = statistics.median(row[key + "_runs"])
        rows.append(row)
    write(rows, args.repeat, args.substeps, args.output)


def write(rows, repeat, substeps, output):
    """The ratios between rows, then contact_scaling.json and .md."""
    for body in ("full", SAVED):
        same = [r for r in rows if r["body"] == body]
        for a, b in zip(same, same[1:]):
            b["substep_ratio_to_previous"] = b["substep_seconds"] / a["substep_seconds"]
            b["solve_ratio_to_previous"] = b["sparse_solve_seconds"] / a["sparse_solve_seconds"]
            # The same without the machine's drift between the two processes: the substep in
            # solves (timed beside each other) times what one solve streams, its factor's
            # nonzeros.
            b["work_ratio_to_previous"] = (b["substep_per_solve"] / a["substep_per_solve"]) * (
                b["factor_nonzeros"] / a["factor_nonzeros"])
    full = [r for r in rows if r["body"] == "full"]
    for r in full:  # the factor's slipping rows against GCR's, in this run
        gcr = [g for g in rows if g["body"] == "full, slips by GCR" and g["requested"] == r["requested"]]
        if gcr:
            r["gcr_substep_ratio"] = gcr[0]["substep_seconds"] / r["substep_seconds"]
            r["gcr_held_solves_ratio"] = gcr[0]["held_solves"] / r["held_solves"]
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / f"{output}.json").write_text(json.dumps({"scene": SCENE, "substeps": substeps, "repeat": repeat,
                                                         "rows": rows}, indent=1))
    lines = ["# What a refined contact boundary costs", "",
             f"`.venv/bin/python benchmarks/contact_scaling.py` ({substeps} substeps): the pad, damped "
             "sliding at 20 m/s (F = 0.3, β = 4e-6 s, 1e-6 s substeps) from the static start; wall "
             "times (the median "
             f"of {repeat} runs; a sparse solve timed beside the substeps in each) and the "
             "process's peak memory, each case in a process of its own. *full* is the body as the "
             "FMU takes it (the sparse contact solve from about 100 contact nodes on), with communication "
             "steps of 1e-5 s (10 substeps), *a state saved each step* the same with a state saved "
             "before each step (what the contact solve keeps from step to step, GCR's directions "
             "above all, goes where a state is saved), *condensed* "
             "the solve it had before, *slips by GCR* the sparse solve without its factor's slipping "
             "rows (as it was before them), *reduced* the reduced body (40 modes). The static start's load "
             "paths take the cost model's solve in every row.", "",
             "| contact nodes | unknowns | body | contact solve | static start [s] | one substep [ms] "
             "| × previous | one sparse solve [ms] | substep / solve | × previous in solves × "
             "factor nonzeros | held solves a substep | peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        ratio, work = r.get("substep_ratio_to_previous"), r.get("work_ratio_to_previous")
        solves = r["held_solves_per_substep"] if r["sparse"] else None
        lines.append(
            f"| {r['contact_nodes']} | {r['unknowns']} | {r['body']} | "
            f"{'sparse' if r['sparse'] else 'condensed'} | {r['static_start_seconds']:.2f} | "
            f"{1e3 * r['substep_seconds']:.3g} | {'' if ratio is None else f'{ratio:.1f}'} | "
            f"{1e3 * r['sparse_solve_seconds']:.3g} | {r['substep_per_solve']:.1f} | "
            f"{'' if work is None else f'{work:.1f}'} | "
            f"{'' if solves is None else f'{solves:.1f}'} | {r['peak_memory_mb']:.0f} |")
    (OUT / f"{output}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
