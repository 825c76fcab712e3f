"""A co-simulation master for FMI 2.0 co-simulation FMUs: fixed-step Jacobi (as fmpy's
simulate_ssp and fmpy's container FMU run), an adaptive step by step doubling with rollback
(fmi2GetFMUstate / fmi2SetFMUstate), input slopes passed by the master
(fmi2SetRealInputDerivatives), and strong coupling (a step iterated to convergence with
Aitken relaxation) for stiff couplings.

A System is described as data (System below); connections are "component.variable" pairs.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .fmu import Model


@dataclass
class System:
    """components: name -> FMU path; parameters: "component.variable" -> value;
    connections: (source "component.output", target "component.input");
    record: outputs kept at every communication point ("component.variable");
    bonds: power bonds checked by the adaptive master, (work A, work B, factor): the energy
    that crosses the connection, counted on both sides, A = factor x B;
    scales: typical magnitudes of outputs ("component.output" -> value, default 1), for the
    masters' absolute tolerances and the relaxation's weighting;
    averaged: outputs that are averages over the last step (ContactBody's forces), not
    end-of-step values: strong coupling holds their targets at the guessed average."""
    components: dict
    connections: list
    parameters: dict = field(default_factory=dict)
    record: list = field(default_factory=list)
    bonds: list = field(default_factory=list)
    scales: dict = field(default_factory=dict)
    averaged: list = field(default_factory=list)  # sources whose output is a step average

    def scale(self, path):
        return float(self.scales.get(path, 1.0))

    def component_parameters(self, component):
        prefix = component + "."
        return {k[len(prefix):]: v for k, v in self.parameters.items() if k.startswith(prefix)}


class RollbackError(RuntimeError):
    """A restored FMU state did not give back the outputs it was saved with, bit for bit."""


def _split(path):
    component, _, variable = path.partition(".")
    return component, variable


class Master:
    """Runs a System. Every doStep is counted in .do_steps (per component call)."""

    def __init__(self, system: System):
        self.system = system
        self.models = {name: Model(fmu, name=name) for name, fmu in system.components.items()}
        self.watched = list(dict.fromkeys([s for s, _ in system.connections] + system.record +
                                          [w for a, b, _ in system.bonds for w in (a, b)]))
        self.refs = {p: self.models[_split(p)[0]].variable(_split(p)[1]).valueReference
                     for p in self.watched + [t for _, t in system.connections]}
        self.do_steps = 0

    def close(self):
        for m in self.models.values():
            m.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # --- state of the coupled system -------------------------------------------------------
    def _read(self):
        values = {}
        for p in self.watched:
            c, v = _split(p)
            inst = self.models[c].instance
            read = inst.getReal if self.models[c].variable(v).type == "Real" else inst.getInteger
            values[p] = float(read([self.refs[p]])[0])
        return values

    def initialize(self, start_time=0.0, zero_inputs=False):
        """Initializes every component with its parameters. The first step's inputs are the
        sources' outputs at start_time, or 0 with zero_inputs (as simulate_ssp does)."""
        for name, model in self.models.items():
            model.start(self.system.component_parameters(name), start_time)
        self.time = start_time
        self.values = self._read()
        self.held = ({t: 0.0 for _, t in self.system.connections} if zero_inputs
                     else {t: self.values[s] for s, t in self.system.connections})
        self.previous = None  # (values, h) of the last step, for extrapolated slopes
        self.do_steps = 0

    def save(self):
        states = {n: m.instance.getFMUstate() for n, m in self.models.items()}
        return states, (self.time, dict(self.values), dict(self.held), self.previous)

    def restore(self, snapshot):
        """Back to a saved point; raises RollbackError unless every watched output is back
        bit for bit."""
        states, (time, values, held, previous) = snapshot
        for n, m in self.models.items():
            m.instance.setFMUstate(states[n])
        again = self._read()
        if any(again[p] != values[p] and not (math.isnan(again[p]) and math.isnan(values[p]))
               for p in values):
            raise RollbackError(f"outputs after fmi2SetFMUstate differ from those saved at "
                                f"t = {time}")
        self.time, self.values, self.held, self.previous = time, dict(values), dict(held), previous

    def free(self, snapshot):
        for n, m in self.models.items():
            m.instance.freeFMUstate(snapshot[0][n])

    # --- one communication step --------------------------------------------------------------
    def _do_step(self, h, inputs, slopes=None):
        for target, value in inputs.items():
            model = self.models[_split(target)[0]]
            model.instance.setReal([self.refs[target]], [value])
            if slopes is not None:
                model.instance.setRealInputDerivatives([self.refs[target]], [1], [slopes[target]])
        for name, model in self.models.items():
            model._call(f"{name}: doStep to t = {self.time + h:.9g}", model.instance.doStep,
                        self.time, h, stage="step")
            self.do_steps += 1
        self.previous = (self.values, h)
        self.time += h
        self.values = self._read()

    def step(self, h, extrapolate=False):
        """Jacobi: every input takes its source's output at the step's start, held (or, with
        extrapolate, with the slope of the source's last step)."""
        inputs = dict(self.held)
        slopes = None
        if extrapolate:
            slopes = {t: 0.0 for _, t in self.system.connections}
            if self.previous is not None:
                before, h0 = self.previous
                slopes = {t: (self.values[s] - before[s]) / h0 for s, t in self.system.connections}
        self._do_step(h, inputs, slopes)
        self.held = {t: self.values[s] for s, t in self.system.connections}

    def step_iterated(self, h, tolerance=1e-6, max_iterations=50):
        """Strong coupling: each input ramps across the step from its value at the start to a
        guess of the source's output at the end (or, for an averaged source, is held at a
        guess of its average over the step, so that force x motion is the same on both
        sides); the guesses are iterated (a fixed point with Aitken's relaxation, on
        residuals divided by the sources' scales) until every output matches its guess to
        tolerance x (its scale + |its value|). Returns the iterations; raises RuntimeError if
        they do not converge."""
        connections = self.system.connections
        scale = np.array([self.system.scale(s) for s, _ in connections])
        start = dict(self.held)
        guess = np.array([start[t] for _, t in connections])
        snapshot = self.save()
        try:
            omega, previous_residual = 1.0, None
            for iteration in range(1, max_iterations + 1):
                if iteration > 1:
                    self.restore(snapshot)
                values, slopes = {}, {}
                for (s, t), g in zip(connections, guess):
                    averaged = s in self.system.averaged
                    values[t] = g if averaged else start[t]
                    slopes[t] = 0.0 if averaged else (g - start[t]) / h
                self._do_step(h, values, slopes)
                out = np.array([self.values[s] for s, _ in connections])
                residual = (out - guess) / scale
                if np.all(np.abs(residual) <= tolerance * (1 + np.abs(out) / scale)):
                    self.held = {t: self.values[s] for s, t in connections}
                    return iteration
                if previous_residual is not None:  # Aitken's dynamic relaxation
                    dr = residual - previous_residual
                    denominator = float(dr @ dr)
                    if denominator > 0:
                        omega = -omega * float(previous_residual @ dr) / denominator
                previous_residual = residual
                guess = guess + omega * residual * scale
            raise RuntimeError(f"strong coupling did not converge in {max_iterations} "
                               f"iterations at t = {self.time - h:.9g}")
        finally:
            self.free(snapshot)

    # --- runs -------------------------------------------------------------------------------
    def _row(self):
        return [self.time] + [self.values[p] for p in self.system.record]

    def _result(self, rows):
        names = ["time"] + self.system.record
        return np.array([tuple(r) for r in rows], dtype=[(n, float) for n in names])

    def run_fixed(self, stop_time, h, extrapolate=False, iterate=False, tolerance=1e-6,
                  start_time=0.0, zero_inputs=False):
        """Fixed communication step h (Jacobi, or strongly coupled with iterate). Returns the
        recorded outputs at every communication point (structured array)."""
        self.initialize(start_time, zero_inputs)
        rows = [self._row()]
        steps = int(round((stop_time - start_time) / h))
        self.iterations = []
        for _ in range(steps):
            if iterate:
                self.iterations.append(self.step_iterated(h, tolerance))
            else:
                self.step(h, extrapolate)
            rows.append(self._row())
        return self._result(rows)

    def _error(self, start, coarse, fine, scales, rtol, atol):
        """Step-doubling error of the coupled outputs, and the energy residual of the power
        bonds over the step (what one side counted against the other), in units of the
        tolerance."""
        error = 0.0
        for s, _ in self.system.connections:
            error = max(error, abs(fine[s] - coarse[s]) / (atol * scales[s] + rtol * abs(fine[s])))
        for a, b, factor in self.system.bonds:
            mismatch = abs((fine[a] - start[a]) - factor * (fine[b] - start[b]))
            error = max(error, mismatch / (atol * scales[a] + rtol * abs(fine[a] - start[a])))
        return error

    def run_adaptive(self, stop_time, rtol=1e-3, atol=1e-3, h0=1e-5, h_min=1e-7, h_max=1e-3,
                     extrapolate=True, scales=None, start_time=0.0, estimator="doubling"):
        """Step doubling: from the accepted point, one step of 2h and, after rolling every
        FMU back, two of h; the error is their difference on the connected outputs (and the
        power bonds' mismatch), against atol x scale + rtol x |value|. Accepted: the two
        half steps are kept; the step grows or shrinks with the error (order 1 of the
        held inputs; 2 with extrapolated slopes).
        estimator="input": one step of h, and the error is how far each input the targets
        assumed (held, or extrapolated along its slope) ended from its source's output at the
        step's end (plus the bonds' residual); a rejected step is rolled back. It costs one
        step per accepted step where doubling costs three.
        Returns the recorded outputs at the accepted points; .accepted, .rejected and
        .do_steps count the work."""
        self.initialize(start_time)
        scales = {p: (scales or {}).get(p, self.system.scale(p)) for p in self.watched}
        rows = [self._row()]
        order = 2 if extrapolate else 1
        h = h0
        self.accepted = self.rejected = 0
        while self.time < stop_time - 1e-12 * stop_time:
            h = min(h, 0.5 * (stop_time - self.time))
            start = self.save()
            try:
                if estimator == "doubling":
                    self.step(2 * h, extrapolate)
                    coarse = dict(self.values)
                    self.restore(start)
                    self.step(h, extrapolate)
                    self.step(h, extrapolate)
                else:  # the inputs' end values as the targets assumed them
                    assumed = dict(self.values)
                    if extrapolate and self.previous is not None:
                        before, h0 = self.previous
                        assumed = {p: v + (v - before[p]) / h0 * 2 * h
                                   for p, v in self.values.items()}
                    self.step(2 * h, extrapolate)
                    coarse = assumed
                error = self._error(start[1][1], coarse, self.values, scales, rtol, atol)
                if error <= 1 or h <= h_min:
                    self.accepted += 1
                    rows.append(self._row())
                else:
                    self.restore(start)
                    self.rejected += 1
            finally:
                self.free(start)
            factor = 0.9 * max(error, 1e-10) ** (-1.0 / (order + 1))
            h = float(np.clip(h * min(2.0, max(0.2, factor)), h_min, h_max))
        return self._result(rows)
