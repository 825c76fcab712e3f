"""Python tooling for the ContactBody FMU (FMI 2.0 co-simulation).

- contactbody.fmu: find the FMU, and `Model`, one extracted FMU with one instance that is reset
  between runs (no re-extraction, no os.chdir), with its log messages kept;
- contactbody.study: parameter studies over any parameters and inputs, on dask.distributed;
- contactbody.plots: heat maps and lines over a study's table.
"""
from .fmu import Model, find_fmu

__all__ = ["Model", "find_fmu"]
