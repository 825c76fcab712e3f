"""Cost of a parameter study: 64 points of the default scene (the paper's body,
F = 1.2, 0.02 s at a 1e-4 s communication step; foundation_velocity from 10 to 30 m/s so
that every point differs), measured in one run:

  bare:       the 64 points in a plain loop on one contactbody.Model in this process; the
              time of their doSteps only, and of the whole loop;
  1 worker:   contactbody.study.run_study on a LocalCluster of 1 worker, wall time of the
              call (cluster start-up included, and also reported without it);
  2 workers:  the same on 2 workers.

Per-point overhead: what each point costs its worker beyond its doSteps, in steady state
(dask's task stream, on a running 1-worker cluster); the whole study's overhead
(study wall - bare doSteps) / bare doSteps, which adds the one-time costs (cluster start,
the worker loading the FMU, the table), is reported beside it. Speed-up = 1 worker / 2.
The machine is noisy (identical bare loops differ by up to 20 % between runs, and its speed
drifts over minutes): the runs are repeated in rounds, every ratio is taken within one round,
and the median over the rounds is reported with their range. Writes
benchmarks/results/study.{md,json}.

    .venv/bin/python benchmarks/study_benchmark.py [--points 64]
"""
import argparse
import json
import os
import pathlib
import sys
import tempfile
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")  # as dask's nanny sets it for its workers

import numpy as np  # noqa: E402

from contactbody.fmu import Model, find_fmu  # noqa: E402
from contactbody.study import Study, point_of_key, run_study  # noqa: E402

RESULTS = pathlib.Path(__file__).resolve().parent / "results"
ROUNDS = 5


def study_of(points):
    return Study(stop_time=0.02, output_interval=1e-4,
                 grid={"foundation_velocity": [float(v) for v in np.linspace(10, 30, points)]})


def bare(study):
    """The points in a plain loop: (doStep seconds, whole-loop seconds)."""
    with Model(find_fmu()) as model:
        from contactbody.study import OUTPUTS
        start, dostep = time.perf_counter(), 0.0
        for point in study.expand():
            _, seconds = model.run(point, study.stop_time, study.output_interval, OUTPUTS)
            dostep += seconds
        return dostep, time.perf_counter() - start


def cluster_start(workers):
    """Seconds to start and stop a LocalCluster of this size with a client."""
    from distributed import Client, LocalCluster
    tic = time.perf_counter()
    with LocalCluster(n_workers=workers, threads_per_worker=1, dashboard_address=None) as c:
        with Client(c) as client:
            client.wait_for_workers(workers)
    return time.perf_counter() - tic


def study_run(study, workers, client=None):
    """run_study's wall time (with its own LocalCluster, or on a running one), the points'
    doStep and wall times summed, and on a running 1-worker cluster the per-point overhead
    in steady state (per_point_overhead)."""
    with tempfile.TemporaryDirectory() as out:
        if client is not None and workers == 1:
            from distributed import get_task_stream
            with get_task_stream(client) as stream:
                tic = time.perf_counter()
                df = run_study(study, out, progress=False, dashboard=False,
                               log=lambda *a: None, client=client)
                wall = time.perf_counter() - tic
            per_point = per_point_overhead(stream.data, df)
        else:
            tic = time.perf_counter()
            df = run_study(study, out, workers=workers, progress=False, dashboard=False,
                           log=lambda *a: None, client=client)
            wall = time.perf_counter() - tic
            per_point = None
    assert set(df["status"]) == {"ok"}, df["message"].unique()
    return wall, float(df["dostep_time"].sum()), float(df["wall_time"].sum()), per_point


def per_point_overhead(tasks, df):
    """What each point costs its worker beyond its doSteps, over those doSteps, in steady
    state: from the end of the first point (which also loads the worker's FMU) to the end of
    the last, the worker's time (its points' reset, initialization, output reads, metrics,
    and dask's hand-off between points) minus the points' doSteps. One worker, one thread:
    the points run back to back."""
    runs = sorted((s["start"], s["stop"], t["key"]) for t in tasks for s in t["startstops"]
                  if s["action"] == "compute")
    assert len(runs) == len(df)
    dostep = dict(zip(df["point_id"], df["dostep_time"]))
    later = sum(dostep[point_of_key(key)] for _, _, key in runs[1:])
    return (runs[-1][1] - runs[0][1] - later) / later


def round_metrics(bare_run, own1, own2, running1, running2, start1, start2):
    """The ratios of one round, each from runs made minutes apart at most."""
    dostep, _ = bare_run
    return {
        "per_point_overhead": running1[3],
        "worker_side_overhead": (own1[2] - own1[1]) / own1[1],
        # the whole study against the same points' doSteps in the same run
        "overhead_same_run_running_cluster": (running1[0] - running1[1]) / running1[1],
        "overhead_same_run_with_start": (own1[0] - own1[1]) / own1[1],
        # against the bare loop of the same round (noisier: another process, another moment)
        "overhead_vs_bare_running_cluster": (running1[0] - dostep) / dostep,
        "overhead_vs_bare_with_start": (own1[0] - dostep) / dostep,
        "speedup_2_workers": own1[0] / own2[0],
        "speedup_2_workers_without_start": (own1[0] - start1) / (own2[0] - start2),
        "speedup_2_workers_running_cluster": running1[0] / running2[0],
        # the same doSteps, two at a time: how much the two cores slow each other down
        "dostep_slowdown_2_workers": own2[1] / own1[1],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=64)
    parser.add_argument("--rounds", type=int, default=ROUNDS)
    args = parser.parse_args()
    study = study_of(args.points)
    n = args.points
    from distributed import Client, LocalCluster
    start1, start2 = min(cluster_start(1) for _ in range(2)), min(cluster_start(2) for _ in range(2))
    rounds, seconds = [], {k: [] for k in ["bare doSteps", "bare loop", "own 1", "own 2",
                                           "running 1", "running 2"]}
    with LocalCluster(n_workers=1, threads_per_worker=1, dashboard_address=None) as c1, \
            Client(c1) as one, \
            LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as c2, \
            Client(c2) as two:
        study_run(study, 1, one)  # the running clusters' workers load the FMU once, before
        study_run(study, 2, two)
        for _ in range(args.rounds):
            runs = (bare(study), study_run(study, 1), study_run(study, 2),
                    study_run(study, 1, one), study_run(study, 2, two))
            rounds.append(round_metrics(*runs, start1, start2))
            for key, value in zip(seconds, [runs[0][0], runs[0][1]] + [x[0] for x in runs[1:]]):
                seconds[key].append(value)
    median = {k: float(np.median([r[k] for r in rounds])) for k in rounds[0]}
    spread = {k: (min(r[k] for r in rounds), max(r[k] for r in rounds)) for k in rounds[0]}
    r = {"points": n, "cpu_count": os.cpu_count(), "rounds": args.rounds,
         "cluster_start_1_s": start1, "cluster_start_2_s": start2,
         "median": median, "per_round": rounds,
         "seconds": {k: v for k, v in seconds.items()}}

    def pct(key):
        lo, hi = spread[key]
        return f"**{100 * median[key]:.1f} %** ({100 * lo:.1f} to {100 * hi:.1f})"

    def times(key):
        lo, hi = spread[key]
        return f"**{median[key]:.2f}×** ({lo:.2f} to {hi:.2f})"

    sec = {k: float(np.median(v)) for k, v in seconds.items()}
    md = [
        f"# Study benchmark ({n} points of the default scene, {os.cpu_count()} cores)",
        "",
        "Command: `.venv/bin/python benchmarks/study_benchmark.py`",
        "",
        f"{args.rounds} rounds; each round runs the six below one after the other, and each "
        "ratio is taken within a round. Medians, with the rounds' range in parentheses.",
        "",
        "| what (median over the rounds) | seconds | per point (ms) |",
        "|---|---|---|",
        f"| bare: doSteps only | {sec['bare doSteps']:.2f} | {1e3 * sec['bare doSteps'] / n:.1f} |",
        f"| bare: whole loop (reset, initialization, doSteps, reading outputs) | "
        f"{sec['bare loop']:.2f} | {1e3 * sec['bare loop'] / n:.1f} |",
        f"| study, 1 worker (run_study wall, its own LocalCluster) | {sec['own 1']:.2f} | "
        f"{1e3 * sec['own 1'] / n:.1f} |",
        f"| study, 2 workers (run_study wall, its own LocalCluster) | {sec['own 2']:.2f} | "
        f"{1e3 * sec['own 2'] / n:.1f} |",
        f"| study on a running cluster (client=), 1 worker | {sec['running 1']:.2f} | "
        f"{1e3 * sec['running 1'] / n:.1f} |",
        f"| study on a running cluster (client=), 2 workers | {sec['running 2']:.2f} | "
        f"{1e3 * sec['running 2'] / n:.1f} |",
        f"| LocalCluster start + stop, 1 worker / 2 workers (best of 2) | {start1:.2f} / "
        f"{start2:.2f} | |",
        "",
        f"- per-point overhead (target 5 %): {pct('per_point_overhead')}. What a point costs "
        "its worker beyond its doSteps (reset, initialization, output reads, metrics, and "
        "dask's hand-off to the next point), over those doSteps, in steady state: dask's task "
        "stream on a running 1-worker cluster, from the end of the first point to the end of "
        f"the last. Inside the points alone (their wall time against their doSteps): "
        f"{pct('worker_side_overhead')}",
        f"- the whole study, one-time costs included, against the doSteps of the same points "
        f"in the same run: {pct('overhead_same_run_running_cluster')} on a running cluster "
        f"(`client=`), {pct('overhead_same_run_with_start')} with run_study's own "
        "LocalCluster",
        f"- the same against the round's bare loop: {pct('overhead_vs_bare_running_cluster')} "
        f"on a running cluster, {pct('overhead_vs_bare_with_start')} with the LocalCluster "
        "(another process at another moment: the noisy comparison on this machine)",
        f"- 2 workers against 1 (target 1.7×): {times('speedup_2_workers')} with the "
        f"LocalCluster, {times('speedup_2_workers_without_start')} without its start-up, "
        f"{times('speedup_2_workers_running_cluster')} on a running cluster. The same "
        f"doSteps took {times('dostep_slowdown_2_workers')} as long in all two at a time as "
        "one at a time",
    ]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "study.json").write_text(json.dumps(r, indent=1))
    (RESULTS / "study.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
