"""A study's settings: the TOML schema, its checks, the points and their identity."""
from __future__ import annotations

import hashlib
import itertools
import json
import math
import tomllib
from dataclasses import dataclass, field

from ..fmu import Interface, Profile
from ..material import DERIVED, to_fmu


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
