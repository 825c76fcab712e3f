"""What a parameter-study point costs beside its doSteps, piece by piece, on the
default scene in this process:

  initialization: fmi2Reset + setupExperiment + enter/exitInitializationMode, and the first
      doStep after it, when the discretization is kept (same parameters) and when it is
      rebuilt (density toggled between two values, so that the mesh is the same size);
  output reads: the study's 15 outputs per step, through fmpy's getReal/getInteger and
      through contactbody.fmu's preallocated reader, right after a doStep (the FMU computes
      the energies then) and again (cached).

Medians of many repetitions. Writes benchmarks/results/reset.{md,json}.

    .venv/bin/python benchmarks/reset_benchmark.py
"""
import json
import pathlib
import sys
import time

import numpy as np

from contactbody.fmu import Model, _Reader, find_fmu
from contactbody.study import OUTPUTS

RESULTS = pathlib.Path(__file__).resolve().parent / "results"
H = 1e-4


def seconds(f, *args):
    tic = time.perf_counter()
    f(*args)
    return time.perf_counter() - tic


def initialization(model, repeats, rebuild):
    """Median seconds of (reset to initialized, first doStep)."""
    init, first = [], []
    for k in range(repeats):
        values = {"density": 1000.0 + (k % 2) * 1e-9} if rebuild else {}
        init.append(seconds(model.start, values))
        first.append(seconds(model.instance.doStep, 0.0, H))
    return float(np.median(init)), float(np.median(first))


def reads(model, steps):
    """Median seconds per step of reading OUTPUTS: (fmpy after a step, reader after a step,
    fmpy cached, reader cached)."""
    inst = model.instance
    reals = [model.variable(n).valueReference for n in OUTPUTS if model.variable(n).type == "Real"]
    integers = [model.variable(n).valueReference for n in OUTPUTS
                if model.variable(n).type != "Real"]
    reader = _Reader(inst.slave, reals, integers)
    row_r, row_i = np.empty(len(reals)), np.empty(len(integers), dtype=np.int64)

    def by_fmpy():
        inst.getReal(reals)
        inst.getInteger(integers)

    def by_reader():
        reader(row_r, row_i)

    model.start({})
    times = {"fmpy_after_step": [], "reader_after_step": [], "fmpy_cached": [],
             "reader_cached": []}
    t = 0.0
    for k in range(steps):
        inst.doStep(t, H)
        t += H
        fresh, cached = (by_fmpy, by_reader) if k % 2 else (by_reader, by_fmpy)
        times[f"{'fmpy' if fresh is by_fmpy else 'reader'}_after_step"].append(seconds(fresh))
        for f in (by_fmpy, by_reader):
            times[f"{'fmpy' if f is by_fmpy else 'reader'}_cached"].append(seconds(f))
    return {k: float(np.median(v)) for k, v in times.items()}


def main():
    with Model(find_fmu()) as model:
        model.start({})
        kept = initialization(model, 200, rebuild=False)
        rebuilt = initialization(model, 200, rebuild=True)
        r = reads(model, 400)
        model.start({})
        step = float(np.median([seconds(model.instance.doStep, H * k, H) for k in range(200)]))
    result = {"initialization_kept_s": kept[0], "first_step_kept_s": kept[1],
              "initialization_rebuilt_s": rebuilt[0], "first_step_rebuilt_s": rebuilt[1],
              "step_s": step, **{f"read_{k}_s": v for k, v in r.items()}}
    us = lambda x: f"{1e6 * x:.1f}"  # noqa: E731
    md = ["# Per-point costs beside the doSteps (default scene)", "",
          "Command: `.venv/bin/python benchmarks/reset_benchmark.py` (medians, µs)", "",
          "| what | discretization kept across fmi2Reset | rebuilt |", "|---|---|---|",
          f"| fmi2Reset to initialized | {us(kept[0])} | {us(rebuilt[0])} |",
          f"| first doStep (1e-4 s, 25 substeps) | {us(kept[1])} | {us(rebuilt[1])} |", "",
          f"A later doStep: {us(step)} µs.", "",
          "| reading the study's 15 outputs | right after a doStep | again |", "|---|---|---|",
          f"| fmpy getReal + getInteger | {us(r['fmpy_after_step'])} | {us(r['fmpy_cached'])} |",
          f"| contactbody.fmu reader (ctypes arrays made once) | {us(r['reader_after_step'])} "
          f"| {us(r['reader_cached'])} |", "",
          "Right after a doStep the FMU computes the energies (two sparse products) for the "
          "first read."]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "reset.json").write_text(json.dumps(result, indent=1))
    (RESULTS / "reset.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))
    return 0


if __name__ == "__main__":
    sys.exit(main())
