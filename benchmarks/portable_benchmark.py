"""The portable FMU against the one before it, in one run: size, simulate_fmu's
start-up share and where it goes, and the cost per substep against its floor at nx = 20..160.

"Before" is commit 406a316 built as it was (gcc 12, Debian's SuiteSparse, METIS and LAPACK as
13 shared libraries beside the .so): the script checks it out as a git worktree in
build-before/406a316/ and builds it there once (needs the Debian packages libsuitesparse-dev and
patchelf, which scripts/setup.sh installs). "After" is build/ (scripts/setup.sh).

Writes benchmarks/results/portable.md and portable.json.

    .venv/bin/python benchmarks/portable_benchmark.py [--rounds N]
    .venv/bin/python benchmarks/portable_benchmark.py --startup-only   # build/'s share only

--startup-only measures build/ alone (no "before" build) and writes benchmarks/results/startup.json.
"""
import argparse
import json
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import zipfile

import fmpy
from build_commit import build_commit
from fmpy import simulate_fmu
from fmpy.fmi2 import FMU2Slave

ROOT = pathlib.Path(__file__).resolve().parents[1]
BEFORE_COMMIT = "406a316"
OUT = ROOT / "benchmarks" / "results"
SIZES = [20, 40, 80, 160]


def build_before():
    """The FMU and bench_substep of BEFORE_COMMIT, built once."""
    build = build_commit(BEFORE_COMMIT, ["fmu", "bench_substep"])
    return {"fmu": build / "ContactBody.fmu", "bench": build / "bench_substep"}


def size(fmu):
    with zipfile.ZipFile(fmu) as z:
        infos = [i for i in z.infolist() if i.filename.startswith("binaries/linux64/")
                 and not i.is_dir()]
        return {"zipped_MB": fmu.stat().st_size / 1e6,
                "linux64_files": len(infos),
                "linux64_unpacked_MB": sum(i.file_size for i in infos) / 1e6,
                "platforms": sorted({i.filename.split("/")[1] for i in z.infolist()
                                     if i.filename.startswith("binaries/") and
                                     i.filename.count("/") >= 2 and not i.is_dir()})}


def simulate_seconds(fmu, stop_time):
    t0 = time.perf_counter()
    simulate_fmu(str(fmu), stop_time=stop_time, output_interval=1e-4)
    return time.perf_counter() - t0


def startup_pieces(fmu):
    """What simulate_fmu does before and after the steps, piece by piece (seconds)."""
    pieces = {}
    t0 = time.perf_counter()
    md = fmpy.read_model_description(str(fmu), validate=True)
    pieces["read + validate modelDescription"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    # as simulate_fmu does: only binaries/ and resources/
    directory = fmpy.extract(str(fmu), include=lambda n: n.startswith(("resources", "binaries/")))
    pieces["extract binaries/ (all platforms)"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    inst = FMU2Slave(guid=md.guid, unzipDirectory=directory,
                     modelIdentifier=md.coSimulation.modelIdentifier, instanceName="bench")
    pieces["load the binary (dlopen)"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    inst.instantiate()
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.exitInitializationMode()
    pieces["instantiate + initialize (mesh, assembly)"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    inst.doStep(0, 1e-4)
    pieces["first doStep (factorization + 25 substeps)"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    inst.doStep(1e-4, 1e-4)
    pieces["a later doStep (25 substeps)"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    inst.terminate()
    inst.freeInstance()
    fmpy.freeLibrary(inst.dll._handle)
    shutil.rmtree(directory, ignore_errors=True)
    pieces["terminate, free, unload, remove"] = time.perf_counter() - t0
    return pieces


def bench_substep(binary, nx):
    dt = 8e-6 * 10 / nx  # the paper's ladder, as benchmarks/run_benchmarks.py
    out = subprocess.run([str(binary), str(nx), repr(dt), str(max(100, 40000 // nx))],
                         capture_output=True, text=True, check=True)
    r = json.loads(out.stdout)
    return {"substep_us": r["per_substep"] * 1e6, "floor_us": r["floor_solve"] * 1e6}


def median_and_range(values):
    return {"median": statistics.median(values), "min": min(values), "max": max(values)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--startup-only", action="store_true",
                        help="only build/'s start-up share and its pieces (startup.json)")
    args = parser.parse_args()
    if args.startup_only:
        fmu = ROOT / "build" / "ContactBody.fmu"
        simulate_seconds(fmu, 1e-4)
        shares = [simulate_seconds(fmu, 1e-4) / simulate_seconds(fmu, 0.02)
                  for _ in range(args.rounds)]
        s = median_and_range(shares)
        pieces = [startup_pieces(fmu) for _ in range(args.rounds)]
        result = {"rounds": args.rounds, "share": s, "zipped_MB": fmu.stat().st_size / 1e6,
                  "pieces_ms": {p: statistics.median(1e3 * r[p] for r in pieces)
                                for p in pieces[0]}}
        OUT.mkdir(parents=True, exist_ok=True)
        (OUT / "startup.json").write_text(json.dumps(result, indent=1) + "\n")
        print(f"start-up share of a default simulate_fmu: {100 * s['median']:.1f} % "
              f"(range {100 * s['min']:.1f}-{100 * s['max']:.1f} %, {args.rounds} rounds)")
        for piece, ms in result["pieces_ms"].items():
            print(f"  {piece}: {ms:.1f} ms")
        return
    builds = {"before": build_before(),
              "after": {"fmu": ROOT / "build" / "ContactBody.fmu",
                        "bench": ROOT / "build" / "linux64" / "bench_substep"}}
    result = {"before_commit": BEFORE_COMMIT, "rounds": args.rounds,
              "size": {k: size(b["fmu"]) for k, b in builds.items()}}

    # Start-up share: a one-step run against the whole default scene (0.02 s), every ratio
    # within one round (this machine's speed drifts), rounds interleaved between the builds.
    for b in builds.values():  # warm the page cache and fmpy's imports
        simulate_seconds(b["fmu"], 1e-4)
    shares = {k: [] for k in builds}
    one_step = {k: [] for k in builds}
    whole = {k: [] for k in builds}
    pieces = {k: [] for k in builds}
    for _ in range(args.rounds):
        for k, b in builds.items():
            s1 = simulate_seconds(b["fmu"], 1e-4)
            s2 = simulate_seconds(b["fmu"], 0.02)
            one_step[k].append(s1)
            whole[k].append(s2)
            shares[k].append(s1 / s2)
            pieces[k].append(startup_pieces(b["fmu"]))
    result["startup"] = {
        k: {"one_step_run_ms": median_and_range([1e3 * s for s in one_step[k]]),
            "default_scene_ms": median_and_range([1e3 * s for s in whole[k]]),
            "share": median_and_range(shares[k]),
            "pieces_ms": {p: statistics.median(1e3 * r[p] for r in pieces[k])
                          for p in pieces[k][0]}}
        for k in builds}

    # Per substep against the floor, both builds in each round.
    substep = {k: {nx: [] for nx in SIZES} for k in builds}
    for _ in range(args.rounds):
        for nx in SIZES:
            for k, b in builds.items():
                substep[k][nx].append(bench_substep(b["bench"], nx))
    result["substep"] = {
        str(nx): {k: {"substep_us": min(r["substep_us"] for r in substep[k][nx]),
                      "floor_us": min(r["floor_us"] for r in substep[k][nx])} for k in builds}
        for nx in SIZES}

    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "portable.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "portable.md").write_text(report(result))
    print(report(result))


def report(r):
    s, st = r["size"], r["startup"]
    lines = [
        "# The portable FMU against the one before it", "",
        f"`.venv/bin/python benchmarks/portable_benchmark.py --rounds {r['rounds']}`; before = "
        f"commit {r['before_commit']} as it was built (gcc 12, Debian's shared libraries "
        "bundled), after = build/ (linux64: zig, glibc 2.17; win64: MinGW-w64). Medians over "
        "the rounds with their range; each ratio is taken within one round.", "",
        "## Size", "",
        "| build | platforms | zipped [MB] | files in binaries/linux64 | linux64 unpacked [MB] |",
        "|---|---|---|---|---|"]
    for k in ("before", "after"):
        lines.append(f"| {k} | {', '.join(s[k]['platforms'])} | {s[k]['zipped_MB']:.2f} | "
                     f"{s[k]['linux64_files']} | {s[k]['linux64_unpacked_MB']:.2f} |")
    lines += ["", "## simulate_fmu start-up: a one-step run against the default scene (0.02 s)", "",
              "| build | one-step run [ms] | default scene [ms] | start-up share |", "|---|---|---|---|"]
    for k in ("before", "after"):
        a, b, c = st[k]["one_step_run_ms"], st[k]["default_scene_ms"], st[k]["share"]
        lines.append(f"| {k} | {a['median']:.1f} ({a['min']:.1f}-{a['max']:.1f}) | "
                     f"{b['median']:.1f} ({b['min']:.1f}-{b['max']:.1f}) | "
                     f"{100 * c['median']:.1f} % ({100 * c['min']:.1f}-{100 * c['max']:.1f}) |")
    lines += ["", "Where a start-up goes (fmpy's calls one by one, median ms):", "",
              "| piece | before | after |", "|---|---|---|"]
    for p in st["before"]["pieces_ms"]:
        lines.append(f"| {p} | {st['before']['pieces_ms'][p]:.2f} | {st['after']['pieces_ms'][p]:.2f} |")
    lines += ["", "## Per substep against the floor (paper scene, F = 1.2, the paper's dt ladder; "
              "best of the rounds)", "",
              "| nx | before substep [us] | after substep [us] | after / before | before floor [us] | "
              "after floor [us] |", "|---|---|---|---|---|---|"]
    for nx, row in r["substep"].items():
        b, a = row["before"], row["after"]
        lines.append(f"| {nx} | {b['substep_us']:.1f} | {a['substep_us']:.1f} | "
                     f"{a['substep_us'] / b['substep_us']:.3f} | {b['floor_us']:.1f} | {a['floor_us']:.1f} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
