"""A study task for the tests: kills its worker process on the point with nx = 7, as a crash
of the FMU inside the worker would; runs every other point normally."""
import os

from contactbody.study import workers


def crash_on_nx_7(point, study, digest):
    if point.get("nx") == 7:
        os._exit(3)
    return workers._run_on_worker(point, study, digest)
