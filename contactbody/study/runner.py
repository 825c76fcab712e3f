"""Running a study: the cluster, the points not yet in the journal, retries of points whose
worker died, and the settings kept beside the results."""
from __future__ import annotations

import hashlib
import json
import math
import os
import pathlib
import time

import fmpy
import numpy as np

from ..fmu import Interface, find_fmu
from .schema import StudyError, _canonical, Study
from .metrics import METRICS, TIMES, failed_metrics, metric_units
from .workers import _run_on_worker, ShipFMU
from .journal import Table


def _client(workers, scheduler, dashboard=True):
    import dask
    from distributed import Client, LocalCluster
    if scheduler:
        return Client(scheduler), None
    # allowed-failures 0: a point whose worker dies comes back to run_study at once (which
    # runs it once more itself), instead of being retried on 3 more workers.
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster = LocalCluster(n_workers=workers or os.cpu_count(), threads_per_worker=1,
                               processes=True, dashboard_address=":8787" if dashboard else None)
    return Client(cluster), cluster


def _close_cluster(cluster, log) -> None:
    """Closes run_study's own cluster. Where a worker died, its nanny may still be starting
    the next one, and closing then fails inside distributed ("can only join a started
    process", dask/distributed#6973, open; seen once in 700 runs of our tests). Every point is
    recorded by then: that is said, and the table written."""
    try:
        cluster.close()
    except AssertionError as e:
        log(f"the dask cluster did not close cleanly ({e}; dask/distributed#6973); every "
            "point is recorded")


def _key(pid: str) -> str:
    return f"point-{pid}-{time.monotonic_ns()}"


def parameter_columns(df) -> list[str]:
    """The columns of a study table that hold the points' values."""
    other = {"point_id", "status", "message", "stop_time", "output_interval", "average_from",
             *METRICS, *TIMES}
    return [c for c in df.columns if c not in other]


def point_of_key(key: str) -> str:
    """The point_id of a task key made by run_study (as dask's task stream shows it)."""
    return key.split("-")[1]


def keep_settings(out, study: Study, units: dict):
    """out/study.json holds the settings every row of out's table was run with (and the
    study as resolved); a study with other settings is refused, naming what changed. New
    points with the same settings extend the table."""
    path = pathlib.Path(out) / "study.json"
    mine = {**study.settings(), "series": list(study.series)}
    if path.exists():
        theirs = json.loads(path.read_text())
        changed = [f"{k} = {theirs.get(k)!r} there, {v!r} here" for k, v in mine.items()
                   if theirs.get(k) != v]
        if changed:
            raise StudyError(f"{out} holds a study run with other settings ({'; '.join(changed)}"
                             f"): give a new --out, or the same settings to extend it")
        resolved = theirs
        for key in ("fixed", "grid"):  # what this run adds to the record of what ran
            resolved.setdefault(key, {}).update(study.resolved()[key])
        resolved.setdefault("points", []).extend(
            p for p in study.resolved()["points"] if p not in resolved["points"])
    else:
        resolved = study.resolved()
    resolved["units"] = {**metric_units(units), **units, "stop_time": "s", "output_interval": "s",
                         "average_from": "s"}
    pathlib.Path(out).mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(json.dumps(resolved, indent=1) + "\n")
    os.replace(tmp, path)


def run_study(study: Study, out, fmu=None, workers: int | None = None,
              scheduler: str | None = None, retry_failed: bool = False, progress: bool = True,
              dashboard: bool = True, log=print, task=None, client=None):
    """Runs the points of `study` not yet in `out`'s table; returns the whole table (pandas),
    with the number of points this call ran in its attrs["ran"]. task: the function run on
    the workers, task(point, study=, digest=) -> (record, series) (default: run the point on
    the worker's model; tests pass one that crashes its worker). client: an existing
    distributed.Client to run on (not closed; workers and scheduler are then ignored)."""
    from distributed import as_completed
    from tqdm import tqdm

    fmu = find_fmu(fmu)
    data = fmu.read_bytes()
    digest = hashlib.sha256(data).hexdigest()[:16]
    interface = Interface(fmpy.read_model_description(str(fmu)))
    study.check(interface)  # names, values and times, before anything runs
    points = study.expand()
    names = sorted({k for p in points for k in p})
    columns = (["point_id", "status", "message"] + names + list(study.settings()) +
               list(METRICS) + TIMES)
    keep_settings(out, study, {v.name: v.unit for v in interface.variables.values()
                               if getattr(v, "unit", None)})
    table = Table(out, columns)
    previous = table.write_parquet()  # in step with the journal (a killed run left it behind)
    done = set(previous["point_id"] if not retry_failed
               else previous.loc[previous["status"] == "ok", "point_id"])
    todo = {}
    for point in points:
        pid = study.point_id(point)
        if pid not in done:
            todo.setdefault(pid, point)
    if todo:
        own = client is None
        if own:
            client, cluster = _client(workers, scheduler, dashboard)
        try:
            if dashboard and client.dashboard_link:
                log(f"dask dashboard: {client.dashboard_link}")
            client.register_plugin(ShipFMU(data, digest))
            task = task or _run_on_worker
            pids = list(todo)
            # One batch, so that the scheduler queues the points and hands them out as workers
            # free up.
            batch = client.map(task, [todo[p] for p in pids], study=study, digest=digest,
                               pure=False, key=[_key(p) for p in pids])
            last_parquet = time.monotonic()
            bar = tqdm(total=len(pids), disable=not progress, desc="points", unit="point")

            def finish(pid, future, second_death=False):
                nonlocal last_parquet
                series = None
                try:
                    record, series = future.result()
                except Exception as e:  # noqa: BLE001 (any failure is the point's record)
                    name = type(e).__name__
                    if name == "KilledWorker" and not second_death:
                        log(f"point {pid}: its worker process died (with every point it "
                            "held); it runs again alone after the others")
                        return False  # run again alone, after the others
                    if name == "KilledWorker":
                        log(f"point {pid}: its worker process died again, alone: recorded "
                            "as failed")
                    why = ("its worker process died while running it, also alone"
                           if name == "KilledWorker" else "the task failed")
                    record = {"status": "failed", "message": f"{why} ({name}: {e})",
                              **failed_metrics(), "wall_time": math.nan,
                              "dostep_time": math.nan}
                future.release()
                record.update({"point_id": pid, **study.settings(),
                               **{k: _canonical(v) for k, v in todo[pid].items()}})
                if series is not None:
                    (table.directory / "series").mkdir(exist_ok=True)
                    # with the point's values, so that a series file stands alone
                    np.savez(table.directory / "series" / f"{pid}.npz", **series,
                             point=json.dumps({k: _canonical(v) for k, v in todo[pid].items()}))
                table.append(record)
                bar.update()
                if time.monotonic() - last_parquet > 5:
                    table.write_parquet()
                    last_parquet = time.monotonic()
                return True

            futures = dict(zip(batch, pids))
            suspects = [futures[f] for f in as_completed(batch) if not finish(futures[f], f)]
            # A dead worker takes down every point it held, not only the one that killed it:
            # each of those runs once more, alone; a second death is its own.
            for pid in suspects:
                alone = client.submit(task, todo[pid], study=study, digest=digest, pure=False,
                                      key=_key(pid))
                finish(pid, alone, second_death=True)
            bar.close()
        finally:
            if own:
                client.close()
                if cluster is not None:
                    _close_cluster(cluster, log)
    df = table.write_parquet()
    df.attrs["ran"] = len(todo)
    return df
