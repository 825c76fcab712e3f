"""Cost of a parameter study (issue 13): 64 points of the default scene (the paper's body,
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
The machine is noisy (identical bare loops differ by up to 20 %): each of the three is run
three times, interleaved, and the best time is kept. Writes benchmarks/results/study.{md,json}.

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
from contactbody.study import Study, run_study  # noqa: E402

RESULTS = pathlib.Path(__file__).resolve().parent / "results"
ROUNDS = 3


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
    later = sum(dostep[key.split("-")[1]] for _, _, key in runs[1:])
    return (runs[-1][1] - runs[0][1] - later) / later


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=64)
    args = parser.parse_args()
    study = study_of(args.points)
    n = args.points
    from distributed import Client, LocalCluster
    runs = {"bare": [], 1: [], 2: [], "running 1": [], "running 2": []}
    with LocalCluster(n_workers=1, threads_per_worker=1, dashboard_address=None) as c1, \
            Client(c1) as one, \
            LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as c2, \
            Client(c2) as two:
        for _ in range(ROUNDS):
            runs["bare"].append(bare(study))
            runs[1].append(study_run(study, 1))
            runs[2].append(study_run(study, 2))
            runs["running 1"].append(study_run(study, 1, one))
            runs["running 2"].append(study_run(study, 2, two))
    dostep, loop = min(runs["bare"])
    wall1, dostep1, point1, _ = min(runs[1])
    wall2, dostep2, _, _ = min(runs[2])
    running1, running_dostep1, _, per_point = min(runs["running 1"])
    running2 = min(runs["running 2"])[0]
    start1, start2 = min(cluster_start(1) for _ in range(2)), min(cluster_start(2) for _ in range(2))
    r = {
        "points": n, "cpu_count": os.cpu_count(),
        "per_point_overhead": per_point,
        "bare_dostep_s": dostep, "bare_loop_s": loop,
        "cluster_start_1_s": start1, "cluster_start_2_s": start2,
        "study_1_worker_s": wall1, "study_2_workers_s": wall2,
        "study_1_worker_dostep_s": dostep1, "study_1_worker_points_s": point1,
        "overhead_per_point": (wall1 - dostep) / dostep,
        "overhead_per_point_without_start": (wall1 - start1 - dostep) / dostep,
        "study_1_worker_running_cluster_s": running1,
        "study_2_workers_running_cluster_s": running2,
        "overhead_per_point_running_cluster": (running1 - dostep) / dostep,
        # against the same points' doSteps in the same run: immune to run-to-run noise
        "overhead_same_run_running_cluster": (running1 - running_dostep1) / running_dostep1,
        "overhead_same_run_with_start": (wall1 - dostep1) / dostep1,
        "speedup_2_workers_running_cluster": running1 / running2,
        "worker_side_overhead": (point1 - dostep1) / dostep1,
        "speedup_2_workers": wall1 / wall2,
        # the same doSteps, two at a time: how much the two cores slow each other down
        "dostep_slowdown_2_workers": dostep2 / dostep1,
        "speedup_2_workers_without_start": (wall1 - start1) / (wall2 - start2),
    }
    md = [
        f"# Study benchmark ({n} points of the default scene, {os.cpu_count()} cores)",
        "",
        "Command: `.venv/bin/python benchmarks/study_benchmark.py`",
        "",
        f"Best of {ROUNDS} interleaved runs each.",
        "",
        "| what | seconds | per point (ms) |",
        "|---|---|---|",
        f"| bare: doSteps only | {dostep:.2f} | {1e3 * dostep / n:.1f} |",
        f"| bare: whole loop (reset, initialization, doSteps, reading outputs) | {loop:.2f} "
        f"| {1e3 * loop / n:.1f} |",
        f"| LocalCluster start + stop, 1 worker / 2 workers | {start1:.2f} / {start2:.2f} | |",
        f"| study, 1 worker (run_study wall) | {wall1:.2f} | {1e3 * wall1 / n:.1f} |",
        f"| study, 2 workers (run_study wall) | {wall2:.2f} | {1e3 * wall2 / n:.1f} |",
        f"| study on a running cluster (client=), 1 worker | {running1:.2f} | {1e3 * running1 / n:.1f} |",
        f"| study on a running cluster (client=), 2 workers | {running2:.2f} | {1e3 * running2 / n:.1f} |",
        "",
        f"- **per-point overhead: {100 * per_point:.1f} %** (target 5 %): what a point costs "
        f"its worker beyond its doSteps (reset, initialization, output reads, metrics, and "
        f"dask's hand-off to the next point), over those doSteps, from the end of the first "
        f"point to the end of the last, on a running 1-worker cluster (dask's task stream)",
        f"- the runner's own cost (1-worker study wall minus the points' wall times on the "
        f"worker): {1e3 * (wall1 - point1) / n:.1f} ms per point",
        f"- per-point overhead of the 1-worker study against the bare doSteps: "
        f"**{100 * r['overhead_per_point']:.1f} %** "
        f"({100 * r['overhead_per_point_without_start']:.1f} % without the cluster start-up; "
        f"on the worker, point wall vs its doSteps: {100 * r['worker_side_overhead']:.1f} %)",
        f"- on a running cluster: **{100 * r['overhead_per_point_running_cluster']:.1f} %** per "
        f"point against the bare doSteps; 2 workers against 1 "
        f"{r['speedup_2_workers_running_cluster']:.2f}×",
        f"- against the doSteps of the same points in the same run (the study's wall time "
        f"minus the time the worker spent in doStep, over that time): "
        f"**{100 * r['overhead_same_run_running_cluster']:.1f} %** on a running cluster, "
        f"{100 * r['overhead_same_run_with_start']:.1f} % with the cluster's start and stop",
        f"- 2 workers against 1: **{r['speedup_2_workers']:.2f}×** "
        f"({r['speedup_2_workers_without_start']:.2f}× without the cluster start-up); the "
        f"same doSteps took {r['dostep_slowdown_2_workers']:.2f}× as long in all, two at a "
        f"time, as one at a time",
    ]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "study.json").write_text(json.dumps(r, indent=1))
    (RESULTS / "study.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
