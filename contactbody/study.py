"""Parameter studies over the ContactBody FMU, on dask.distributed.

A study is a set of points (values for any FMU parameters and inputs, an input possibly a
piecewise linear profile in time) run over the same time span. Each point gives one row of
a tidy table: its values, the metrics below, its status and message, and its wall time.

Execution: a LocalCluster (default; --workers sets its size) or an existing cluster
(--scheduler ADDRESS). A worker plugin ships the FMU's bytes to every worker; each worker
thread extracts it once and keeps one instance, reset (fmi2Reset) between points. The
contactbody package must be importable on the workers (pip install it there).

The table is a journal: each finished point is appended to results.csv at once (one line,
flushed), so a killed study loses nothing finished, and a rerun skips the points already in
it. results.parquet holds the same rows; it is rewritten from the journal as points finish
(at most every 5 s) and at the end. A point whose run fails (a parameter the FMU refuses, a
contact solve that fails, a worker process that dies) is recorded with its message, and the
study goes on. A worker that dies takes down every point it held: those run once more, each
alone on the cluster, after the others; a point whose worker dies again is recorded.
"""
from __future__ import annotations

import csv
import hashlib
import io
import itertools
import json
import math
import os
import pathlib
import threading
import time
import tomllib
from dataclasses import dataclass, field

import fmpy
import numpy as np
from distributed.diagnostics.plugin import WorkerPlugin

from .fmu import Interface, Model, Profile, SimulationFailed, find_fmu
from .material import DERIVED, to_fmu

# Outputs every point reads (the metrics are computed from them).
OUTPUTS = ["energy", "clamp_work", "normal_contact_work", "friction_work", "damping_work",
           "friction_dissipation", "normal_force", "friction_force", "max_penetration",
           "active_contact_nodes", "slipping_contact_nodes", "substeps", "substep_refinements",
           "contact_iterations", "gauss_seidel_sweeps"]

# Per point, in this order (units: J/m, N/m, W/m, m; counts summed over the run).
METRICS = {
    "energy_final": "E at stop_time",
    "energy_max": "largest E at a communication point",
    "balance_error_max": "max |E - E(0) - (clamp + normal contact + friction - damping work)|",
    "normal_force_mean": "mean of normal_force over the averaging window",
    "friction_force_mean": "mean of friction_force over the averaging window",
    "apparent_friction_ratio": "friction_force_mean / normal_force_mean",
    "slip_fraction": "slipping share of the node-steps in contact (averaging window)",
    "stick_fraction": "sticking share of the node-steps in contact (averaging window)",
    "friction_power": "friction_dissipation's growth over the window / its length",
    "damping_power": "damping_work's growth over the window / its length",
    "max_penetration": "largest max_penetration",
    "substeps": "midpoint substeps taken",
    "refinements": "substeps redone as halves after a failed contact solve",
    "contact_iterations": "semi-smooth Newton iterations",
    "iterations_per_substep": "contact_iterations / substeps",
    "gauss_seidel_sweeps": "sweeps of the contact solver's fallback",
}
METRIC_UNITS = {"energy_final": "J/m", "energy_max": "J/m", "balance_error_max": "J/m",
                "normal_force_mean": "N/m", "friction_force_mean": "N/m",
                "friction_power": "W/m", "damping_power": "W/m", "max_penetration": "m",
                "wall_time": "s", "dostep_time": "s"}
TIMES = ["wall_time", "dostep_time"]  # s: the whole point on its worker; its doSteps only


class StudyError(ValueError):
    """A mistake in a study's settings, found before anything runs; the message names the
    file (when there is one) and the key."""


def _canonical(value):
    """A point value as it goes into the table and the point's identity."""
    if isinstance(value, Profile):
        return "profile:" + json.dumps([list(p) for p in zip(value.times, value.values)])
    return value


@dataclass
class Study:
    """stop_time and output_interval (s) for every point; fixed: values common to all points;
    grid: name -> values, whose Cartesian product gives the points; points: explicit points
    (added to the grid's); series: outputs to keep per point as time series (NPZ);
    average_from: start of the averaging window of the mean forces, fractions and powers."""
    stop_time: float
    output_interval: float
    fixed: dict = field(default_factory=dict)
    grid: dict = field(default_factory=dict)
    points: list = field(default_factory=list)
    series: list = field(default_factory=list)
    average_from: float = 0.0

    @staticmethod
    def _value(v):
        if isinstance(v, dict):
            if set(v) != {"profile"}:
                raise ValueError(f"a table value must be {{profile = [[t, v], ...]}}: {v}")
            return Profile.of(v["profile"])
        return v

    @classmethod
    def from_dict(cls, d: dict) -> "Study":
        known = {"stop_time", "output_interval", "fixed", "grid", "points", "series",
                 "average_from"}
        unknown = set(d) - known
        if unknown:
            raise ValueError(f"unknown study keys {sorted(unknown)}; known: {sorted(known)}")
        grid = {}
        for name, values in d.get("grid", {}).items():
            if not isinstance(values, list) or not values:
                raise ValueError(f"grid.{name} must be a non-empty list")
            grid[name] = [cls._value(v) for v in values]
        return cls(stop_time=float(d["stop_time"]), output_interval=float(d["output_interval"]),
                   fixed={k: cls._value(v) for k, v in d.get("fixed", {}).items()},
                   grid=grid,
                   points=[{k: cls._value(v) for k, v in p.items()} for p in d.get("points", [])],
                   series=list(d.get("series", [])),
                   average_from=float(d.get("average_from", 0.0)))

    @classmethod
    def from_toml(cls, path) -> "Study":
        try:
            with open(path, "rb") as f:
                d = tomllib.load(f)
        except tomllib.TOMLDecodeError as e:
            raise StudyError(f"{path}: not a TOML file ({e})") from None
        except OSError as e:
            raise StudyError(f"{path}: cannot be read ({e.strerror})") from None
        try:
            study = cls.from_dict(d)
        except KeyError as e:
            raise StudyError(f"{path}: missing key {e.args[0]!r}") from None
        except (ValueError, TypeError) as e:
            raise StudyError(f"{path}: {e}") from None
        study.source = str(path)
        return study

    source: str = ""  # the study file, for messages

    def check(self, interface: Interface | None = None):
        """Study-level checks, before any cluster starts: the times, and with the FMU's
        interface every name and value against its modelDescription. Raises StudyError
        naming the file and the key."""
        where = f"{self.source}: " if self.source else ""

        def fail(key, why):
            raise StudyError(f"{where}{key}: {why}")

        for key in ("stop_time", "output_interval", "average_from"):
            value = getattr(self, key)
            if not (isinstance(value, (int, float)) and math.isfinite(value)):
                fail(key, f"must be a finite number (got {value!r})")
        if not self.stop_time > 0:
            fail("stop_time", f"must be > 0 s (got {self.stop_time!r})")
        if not self.output_interval > 0:
            fail("output_interval", f"must be > 0 s (got {self.output_interval!r})")
        steps = self.stop_time / self.output_interval
        if abs(steps - round(steps)) > 1e-9 * max(1.0, steps) or round(steps) < 1:
            fail("output_interval", f"{self.output_interval!r} s must divide stop_time "
                 f"{self.stop_time!r} s into whole steps (it gives {steps:.6g})")
        if not 0 <= self.average_from <= self.stop_time - self.output_interval:
            fail("average_from", f"{self.average_from!r} s must be in [0, stop_time - "
                 f"output_interval] = [0, {self.stop_time - self.output_interval:g}] s: the "
                 "averaging window needs at least one output interval")
        if interface is None:
            return
        places = [(f"fixed.{k}", k, v) for k, v in self.fixed.items()]
        places += [(f"grid.{k}", k, v) for k, values in self.grid.items() for v in values]
        places += [(f"points[{i}].{k}", k, v) for i, p in enumerate(self.points)
                   for k, v in p.items()]
        derived = {name for pair in DERIVED for name in pair}
        for key, name, value in places:
            if name in derived:
                if not isinstance(value, (int, float)):
                    fail(key, f"{name} must be a number (got {value!r})")
                continue  # checked below, as the FMU parameters it defines
            try:
                if isinstance(value, Profile):
                    if interface.variable(name).causality != "input":
                        raise ValueError(f"{name} is not an input: it cannot follow a profile")
                else:
                    interface.coerce(name, value)
            except ValueError as e:
                fail(key, str(e))
        points = self.expand()
        for i, point in enumerate(points):  # what each point gives the FMU, derived included
            try:
                for name, value in to_fmu(point).items():
                    if not isinstance(value, Profile):
                        interface.coerce(name, value)
            except ValueError as e:
                fail(f"point {i + 1} of {len(points)} ({point})", str(e))
        for name in self.series:
            try:
                if interface.variable(name).causality != "output":
                    raise ValueError(f"{name} is not an output")
            except ValueError as e:
                fail("series", str(e))

    def expand(self) -> list[dict]:
        """The points, each with the fixed values under its own: the grid's product and the
        explicit points; with neither, the one point of the fixed values."""
        names = list(self.grid)
        points = [dict(zip(names, combo)) for combo in itertools.product(*self.grid.values())]
        if not self.grid and self.points:  # only the explicit points (else the fixed values)
            points = []
        points += [dict(p) for p in self.points]
        return [{**self.fixed, **p} for p in points]

    def settings(self) -> dict:
        return {"stop_time": self.stop_time, "output_interval": self.output_interval,
                "average_from": self.average_from}

    def resolved(self) -> dict:
        """The whole study as it ran (profiles as their [t, v] lists), for study.json."""
        values = lambda d: {k: _canonical(v) for k, v in d.items()}  # noqa: E731
        return {**self.settings(), "series": list(self.series), "fixed": values(self.fixed),
                "grid": {k: [_canonical(v) for v in vs] for k, vs in self.grid.items()},
                "points": [values(p) for p in self.points]}

    def point_id(self, point: dict) -> str:
        """Identity of a point in this study's table: its values and the run's settings."""
        text = json.dumps({"point": {k: _canonical(v) for k, v in point.items()},
                           **self.settings()}, sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:16]


def metrics(s: dict, study: Study) -> dict:
    """The per-point metrics (METRICS) from a run's series."""
    t, e = s["time"], s["energy"]
    balance = (e - e[0]) - (s["clamp_work"] + s["normal_contact_work"] + s["friction_work"] -
                            s["damping_work"])
    # Rows after t0 whose step ends after average_from (row 0 holds the initial reactions).
    window = np.flatnonzero((t > study.average_from) & (np.arange(len(t)) > 0))
    first = max(window[0] - 1, 0) if len(window) else 0
    span = t[-1] - t[first]
    normal = s["normal_force"][window].mean() if len(window) else math.nan
    friction = s["friction_force"][window].mean() if len(window) else math.nan
    active = s["active_contact_nodes"][window].sum()
    slipping = s["slipping_contact_nodes"][window].sum()
    substeps = int(s["substeps"].sum())
    iterations = int(s["contact_iterations"].sum())
    return {
        "energy_final": float(e[-1]),
        "energy_max": float(e.max()),
        "balance_error_max": float(np.abs(balance).max()),
        "normal_force_mean": float(normal),
        "friction_force_mean": float(friction),
        "apparent_friction_ratio": float(friction / normal) if normal > 0 else math.nan,
        "slip_fraction": float(slipping / active) if active > 0 else math.nan,
        "stick_fraction": float((active - slipping) / active) if active > 0 else math.nan,
        "friction_power": float((s["friction_dissipation"][-1] -
                                 s["friction_dissipation"][first]) / span) if span > 0 else math.nan,
        "damping_power": float((s["damping_work"][-1] - s["damping_work"][first]) / span)
        if span > 0 else math.nan,
        "max_penetration": float(s["max_penetration"].max()),
        "substeps": substeps,
        "refinements": int(s["substep_refinements"].sum()),
        "contact_iterations": iterations,
        "iterations_per_substep": iterations / substeps if substeps else math.nan,
        "gauss_seidel_sweeps": int(s["gauss_seidel_sweeps"].sum()),
    }


def failed_metrics() -> dict:
    return {name: math.nan for name in METRICS}


def run_point(model: Model, point: dict, study: Study):
    """Runs one point on `model` (reset first). Returns (record, series): series is None
    unless the study keeps series and the run succeeded."""
    tic = time.perf_counter()
    values = {k: v for k, v in point.items() if not isinstance(v, Profile)}
    inputs = {k: v for k, v in point.items() if isinstance(v, Profile)}
    try:
        values = to_fmu(values)  # youngs_modulus, poisson_ratio, loss_factor, ...
    except ValueError as e:
        return ({"status": "failed", "message": str(e), **failed_metrics(),
                 "wall_time": math.nan, "dostep_time": math.nan}, None)
    outputs = list(dict.fromkeys(OUTPUTS + list(study.series)))
    series, dostep = None, math.nan
    try:
        s, dostep = model.run(values, study.stop_time, study.output_interval, outputs, inputs)
        record = {"status": "ok", "message": "", **metrics(s, study)}
        if study.series:
            series = {k: s[k] for k in ["time"] + list(study.series)}
    except (SimulationFailed, ValueError, KeyError) as e:
        record = {"status": "failed", "message": str(e), **failed_metrics()}
    record["wall_time"] = time.perf_counter() - tic
    record["dostep_time"] = dostep
    return record, series


# --- on the workers -------------------------------------------------------------------------

_fmu_paths: dict[str, pathlib.Path] = {}  # digest -> the worker's copy of the FMU
_models = threading.local()               # digest -> Model, one per worker thread


def _worker_model(digest: str) -> Model:
    models = getattr(_models, "by_digest", None)
    if models is None:
        models = _models.by_digest = {}
    if digest not in models:
        models[digest] = Model(_fmu_paths[digest], name=f"study-{digest[:6]}")
    return models[digest]


def _run_on_worker(point: dict, study: Study, digest: str):
    return run_point(_worker_model(digest), point, study)


class ShipFMU(WorkerPlugin):
    """Writes the FMU's bytes into the worker's directory once (on every worker, including
    those that join or restart later)."""
    idempotent = True

    def __init__(self, data: bytes, digest: str):
        self.data, self.digest = data, digest
        self.name = f"contactbody-fmu-{digest}"

    def setup(self, worker):
        path = pathlib.Path(worker.local_directory) / f"ContactBody-{self.digest}.fmu"
        if not path.exists():
            path.write_bytes(self.data)
        _fmu_paths[self.digest] = path


# --- the table ------------------------------------------------------------------------------

class Table:
    """results.csv (the journal: one flushed line per finished point) and results.parquet."""

    def __init__(self, directory, columns: list[str]):
        self.directory = pathlib.Path(directory)
        self.directory.mkdir(parents=True, exist_ok=True)
        self.csv = self.directory / "results.csv"
        self.parquet = self.directory / "results.parquet"
        self.columns = columns
        if self.csv.exists() and self.csv.stat().st_size > 0:
            with open(self.csv, newline="") as f:
                header = next(csv.reader(f), None)
            if header != columns:
                raise ValueError(f"{self.csv} holds another study's table (columns {header}); "
                                 "give another output directory")
        else:
            self._write_line(columns)

    def _write_line(self, values):
        buffer = io.StringIO()
        csv.writer(buffer).writerow(values)
        fd = os.open(self.csv, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:  # one write: a killed study leaves whole lines (a torn last one is ignored)
            os.write(fd, buffer.getvalue().encode())
            os.fsync(fd)
        finally:
            os.close(fd)

    def append(self, record: dict):
        self._write_line([_format(record.get(c)) for c in self.columns])

    def frame(self):
        import pandas as pd
        with open(self.csv, newline="") as f:
            text = f.read()
        if not text.endswith("\n"):  # the last line of a killed run may be torn
            text = text[:text.rfind("\n") + 1]
        # a parameter a point does not set: NaN
        df = pd.read_csv(io.StringIO(text), dtype={"message": str, "status": str})
        df["message"] = df["message"].fillna("")
        return df.drop_duplicates("point_id", keep="last").reset_index(drop=True)

    def write_parquet(self):
        df = self.frame()
        tmp = self.parquet.with_suffix(".parquet.tmp")
        df.to_parquet(tmp, index=False)
        os.replace(tmp, self.parquet)
        return df


def _format(value):
    if isinstance(value, float):
        return repr(value)  # round-trips exactly
    return "" if value is None else value


# --- the runner -----------------------------------------------------------------------------

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
    resolved["units"] = {**METRIC_UNITS, **units, "stop_time": "s", "output_interval": "s",
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
                    cluster.close()
    df = table.write_parquet()
    df.attrs["ran"] = len(todo)
    return df
