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

Modules: schema (the settings), metrics (what a point yields), workers (the dask side),
journal (the table), runner (run_study).
"""
from .journal import Table
from .metrics import METRIC_UNITS, METRICS, OUTPUTS, TIMES, failed_metrics, metric_units, metrics, run_point
from .runner import keep_settings, parameter_columns, point_of_key, run_study
from .schema import Study, StudyError
from .workers import ShipFMU

__all__ = ["METRICS", "METRIC_UNITS", "metric_units", "OUTPUTS", "TIMES", "ShipFMU", "Study", "StudyError", "Table",
           "failed_metrics", "keep_settings", "metrics", "parameter_columns", "point_of_key",
           "run_point", "run_study"]
