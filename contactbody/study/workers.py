"""On the dask workers: the FMU shipped once to each (a worker plugin), one model per worker
thread, reset between points."""
from __future__ import annotations

import pathlib
import threading

from distributed.diagnostics.plugin import WorkerPlugin

from ..fmu import Model
from .schema import Study
from .metrics import run_point


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
