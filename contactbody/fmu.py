"""The ContactBody FMU from Python: where it is, and `Model`, one extracted FMU with one
instance that runs any number of simulations (fmi2Reset between them).

fmpy's simulate_fmu extracts the FMU on every call and changes the working directory; a
parameter study calls it thousands of times. Model extracts once, keeps its instance, and
passes input slopes itself (fmi2SetRealInputDerivatives), which simulate_fmu cannot for this
FMU (fmpy 0.3.32 allocates derivative slots for exactly 9 inputs).
"""
from __future__ import annotations

import ctypes
import difflib
import io
import itertools
import math
import os
import pathlib
import shutil
import tempfile
import time
import zipfile
from dataclasses import dataclass

import fmpy
import numpy as np
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
from fmpy.logging import addLoggerProxy

ROOT = pathlib.Path(__file__).resolve().parents[1]


# Where the wheel (contactbody.tools.release) puts the FMUs: package data, beside this file.
PACKAGED = pathlib.Path(__file__).resolve().parent / "fmus"


def find_fmu(path: str | os.PathLike | None = None) -> pathlib.Path:
    """The FMU to use: `path` if given, else $CONTACTBODY_FMU, else build/ContactBody.fmu of
    this checkout (scripts/setup.sh builds it there), else the one the installed wheel carries.
    The companion FMUs (BeltDrive, Press) are found beside it."""
    chosen = path or os.environ.get("CONTACTBODY_FMU")
    if chosen:
        candidate = pathlib.Path(chosen).expanduser().resolve()
    else:
        built = ROOT / "build" / "ContactBody.fmu"
        candidate = built if built.is_file() else PACKAGED / "ContactBody.fmu"
    if not candidate.is_file():
        raise FileNotFoundError(f"no FMU at {candidate}: build it with scripts/setup.sh, install "
                                "the contactbody wheel that carries it, or give its path "
                                "(argument or CONTACTBODY_FMU)")
    return candidate


def simulate_fmi3(fmu: str | os.PathLike | None = None, start_values: dict | None = None,
                  **kwargs):
    """fmpy.simulate_fmu for the FMI 3.0 FMU (ContactBody_fmi3.fmu beside find_fmu()'s), with
    any mesh. fmpy 0.3.32 neither enters Configuration Mode nor sizes the edge arrays by the
    structural parameter: it takes their size from the modelDescription's start of
    `edge_nodes`, so `start_values={"nx": 40}` alone makes the FMU refuse the first array read
    (rightly: its arrays hold 41 values). Here a new nx, ny or mesh goes into a configured copy
    (configured_copy below: them, and edge_nodes = nx + 1 or the mesh's contact
    nodes, as start values), which is run and removed; the other start values and keyword
    arguments pass to simulate_fmu."""

    path = pathlib.Path(fmu) if fmu else find_fmu().with_name("ContactBody_fmi3.fmu")
    start_values = dict(start_values or {})
    mesh = {k: start_values.pop(k) for k in ("nx", "ny", "mesh") if k in start_values}
    if not mesh:
        return fmpy.simulate_fmu(str(path), start_values=start_values, **kwargs)
    directory = tempfile.mkdtemp(prefix="ContactBody_fmi3_")
    try:
        copy = pathlib.Path(directory) / path.name
        copy.write_bytes(configured_copy(path, mesh))
        return fmpy.simulate_fmu(str(copy), start_values=start_values, **kwargs)
    finally:
        shutil.rmtree(directory, ignore_errors=True)


# fmpy's native logger proxy (which formats the variadic message) holds one Python callback
# for the whole process: messages are routed to their instance by instance name.
_messages_by_instance: dict[str, list] = {}


def _log(_env, name, status, category, message):
    _messages_by_instance.setdefault(name.decode(), []).append(
        (status, category.decode(), message.decode()))


_logger = fmi2CallbackLoggerTYPE(_log)
_serial = itertools.count()


class Instance:
    """An fmpy FMU2Slave whose log messages are kept in .messages as (status, category, text).
    Other attributes are the FMU2Slave's (doStep, getReal, ...)."""

    def __init__(self, model_description, unzipped, name="instance", logging_on=False):
        self.name = f"{name}#{next(_serial)}"
        self.types = {v.name: (v.type, v.valueReference) for v in model_description.modelVariables}
        self.messages = _messages_by_instance.setdefault(self.name, [])
        self.slave = FMU2Slave(guid=model_description.guid, unzipDirectory=str(unzipped),
                               modelIdentifier=model_description.coSimulation.modelIdentifier,
                               instanceName=self.name)
        self.callbacks = fmi2CallbackFunctions()
        self.callbacks.logger = _logger
        addLoggerProxy(ctypes.byref(self.callbacks))
        try:
            self.slave.instantiate(callbacks=self.callbacks, loggingOn=logging_on)
        except Exception as error:  # fmpy says only "Failed to instantiate model": add the log
            raise RuntimeError(f"{error}; the FMU's log: {self.text() or '(empty)'}") from error

    def __getattr__(self, name):
        return getattr(self.slave, name)

    def set_values(self, values: dict):
        """Sets each variable of `values` by name, with the setter of its type."""
        for name, value in values.items():
            kind, vr = self.types[name]
            {"String": self.slave.setString, "Real": self.slave.setReal}.get(kind, self.slave.setInteger)([vr], [value])

    def text(self):
        return "\n".join(m[2] for m in self.messages)

    def close(self):
        self.slave.freeInstance()
        _messages_by_instance.pop(self.name, None)

    def free_library(self):
        self.slave.freeLibrary()


@dataclass(frozen=True)
class Profile:
    """An input given as a piecewise linear function of time: values at increasing times,
    held constant outside them."""
    times: tuple
    values: tuple

    @staticmethod
    def of(pairs) -> "Profile":
        """From [[t0, v0], [t1, v1], ...]."""
        times, values = zip(*((float(t), float(v)) for t, v in pairs))
        if any(b <= a for a, b in zip(times, times[1:])):
            raise ValueError(f"profile times must increase: {times}")
        return Profile(times, values)

    def value(self, t: float) -> float:
        return float(np.interp(t, self.times, self.values))

    def slope(self, t: float) -> float:
        """Slope of the segment that starts at or before t (0 outside the profile)."""
        k = int(np.searchsorted(self.times, t, side="right")) - 1
        if k < 0 or k + 1 >= len(self.times):
            return 0.0
        return (self.values[k + 1] - self.values[k]) / (self.times[k + 1] - self.times[k])


class _Reader:
    """Reads a fixed list of Real and Integer outputs into two rows per call. fmpy's getReal
    builds its ctypes arrays and a list on every call, half the cost of reading a step's
    outputs; these are built once."""

    def __init__(self, slave, reals, integers):
        self.slave, self.component = slave, slave.component
        self.real_refs = (ctypes.c_uint * len(reals))(*reals)
        self.integer_refs = (ctypes.c_uint * len(integers))(*integers)
        self.real_values = (ctypes.c_double * len(reals))()
        self.integer_values = (ctypes.c_int * len(integers))()
        self.reals = np.ctypeslib.as_array(self.real_values) if reals else None
        self.integers = np.ctypeslib.as_array(self.integer_values) if integers else None

    def __call__(self, real_row, integer_row):
        if self.reals is not None:
            self.slave.fmi2GetReal(self.component, self.real_refs, len(self.real_refs),
                                   self.real_values)
            real_row[:] = self.reals
        if self.integers is not None:
            self.slave.fmi2GetInteger(self.component, self.integer_refs,
                                      len(self.integer_refs), self.integer_values)
            integer_row[:] = self.integers


class SimulationFailed(RuntimeError):
    """An FMI call failed; the message carries the FMU's own error messages. stage is
    "initialization" or "step"; series holds the rows up to the failed step (run only)."""

    def __init__(self, message, stage, series=None):
        super().__init__(message)
        self.stage, self.series = stage, series


class Interface:
    """The FMU's variables by name, from its model description, and how values are given."""

    def __init__(self, description):
        self.description = description
        self.variables = {v.name: v for v in description.modelVariables}
        self.enumerations = {t.name: {item.name: int(item.value) for item in t.items}
                             for t in description.typeDefinitions if t.type == "Enumeration"}

    def variable(self, name):
        try:
            return self.variables[name]
        except KeyError:
            close = difflib.get_close_matches(name, self.variables, n=3)
            hint = f"; did you mean {' or '.join(close)}?" if close else ""
            raise ValueError(f"the FMU has no variable {name!r}{hint}") from None

    def coerce(self, name, value):
        """A value as the FMU takes it: enumeration names (mass_matrix = 'redistributed_both')
        become their integers; Real, Integer and String values are checked for type."""
        v = self.variable(name)
        if v.causality not in ("parameter", "input"):
            raise ValueError(f"{name} is an {v.causality}, not a parameter or an input")
        if v.type == "Enumeration":
            items = self.enumerations[v.declaredType.name]
            if isinstance(value, str):
                if value not in items:
                    close = difflib.get_close_matches(value, items, n=1)
                    hint = f"; did you mean {close[0]!r}?" if close else ""
                    raise ValueError(f"{name} = {value!r}: not one of {sorted(items)}{hint}")
                return items[value]
            if float(value) != int(value) or int(value) not in items.values():
                raise ValueError(f"{name} = {value!r}: not one of {sorted(items.values())} "
                                 f"({', '.join(f'{k} = {i}' for k, i in items.items())})")
            return int(value)
        if v.type == "Integer":
            if isinstance(value, str) or float(value) != int(value):
                raise ValueError(f"{name} = {value!r}: not an integer")
            return self._in_range(v, int(value))
        if v.type == "String":
            return str(value)
        if isinstance(value, str):
            raise ValueError(f"{name} = {value!r}: not a number")
        return self._in_range(v, float(value))

    @staticmethod
    def _in_range(v, value):
        """The modelDescription's limits are exactly what the FMU refuses (tested)."""
        if not math.isfinite(value):
            raise ValueError(f"{v.name} = {value!r}: must be finite")
        low = None if v.min is None else float(v.min)
        high = None if v.max is None else float(v.max)
        if (low is not None and value < low) or (high is not None and value > high):
            unit = f" {v.unit}" if getattr(v, "unit", None) else ""
            raise ValueError(f"{v.name} = {value!r}{unit}: out of range [{low}, {high}]")
        return value


class Model(Interface):
    """One extracted FMU and one instance of it, reused for every run."""

    def __init__(self, fmu=None, name="contactbody"):
        self.path = find_fmu(fmu)
        super().__init__(fmpy.read_model_description(str(self.path)))
        self.directory = tempfile.mkdtemp(prefix="ContactBody_")
        fmpy.extract(str(self.path), self.directory)
        self.name = name
        self.instance = Instance(self.description, self.directory, name)
        self._used = False

    def close(self):
        if self.instance is not None:
            self.instance.close()
            self.instance.free_library()
            self.instance = None
        shutil.rmtree(self.directory, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def set_values(self, values: dict):
        for name, value in values.items():
            v, x = self.variable(name), self.coerce(name, value)
            if v.type == "Real":
                self.instance.setReal([v.valueReference], [x])
            elif v.type == "String":
                self.instance.setString([v.valueReference], [x])
            else:
                self.instance.setInteger([v.valueReference], [x])

    def _failure(self, what, e, before, stage, series=None):
        """The SimulationFailed of a failed call, with the FMU's error messages logged since
        message number `before`."""
        errors = [m[2] for m in self.instance.messages[before:] if m[0] >= 2]
        return SimulationFailed(f"{what}: " + ("; ".join(errors) or str(e)), stage, series)

    def _call(self, what, f, *args, stage="initialization"):
        before = len(self.instance.messages)
        try:
            return f(*args)
        except FMICallException as e:
            raise self._failure(what, e, before, stage) from None

    def start(self, values: dict, start_time: float = 0.0):
        """Resets the instance if it has run before, and initializes it with these values
        (parameters and input start values)."""
        if self._used:
            try:
                self.instance.reset()
            except FMICallException:  # a failed reset: start over with a new instance
                self.instance.close()
                self.instance = Instance(self.description, self.directory, self.name)
        self._used = True
        self.instance.messages.clear()
        self._call("setupExperiment", self.instance.setupExperiment, None, start_time)
        self._call("enterInitializationMode", self.instance.enterInitializationMode)
        self._call("setting values", self.set_values, values)
        self._call("exitInitializationMode", self.instance.exitInitializationMode)

    def run(self, values: dict, stop_time: float, output_interval: float, outputs,
            inputs: dict | None = None, start_time: float = 0.0):
        """Simulates from start_time to stop_time in steps of output_interval.

        values: parameters and constant inputs by name; inputs: input name -> Profile,
        passed as value and slope at every communication point (exact for profiles whose
        breakpoints are communication points). Returns (series, seconds): series maps "time"
        and every output to an array with one row per communication point, the first at
        start_time; seconds is the time spent in doStep."""
        inputs = inputs or {}
        start = dict(values)
        for name, profile in inputs.items():
            if self.variable(name).causality != "input":
                raise ValueError(f"{name} is not an input: it cannot follow a profile")
            start[name] = profile.value(start_time)
        self.start(start, start_time)
        steps = int(round((stop_time - start_time) / output_interval))
        if steps < 1 or abs(start_time + steps * output_interval - stop_time) > 1e-9 * stop_time:
            raise ValueError(f"stop_time - start_time must be a multiple of output_interval")
        reals = [self.variable(n).valueReference for n in outputs
                 if self.variable(n).type == "Real"]
        integers = [self.variable(n).valueReference for n in outputs
                    if self.variable(n).type != "Real"]
        real_names = [n for n in outputs if self.variable(n).type == "Real"]
        integer_names = [n for n in outputs if self.variable(n).type != "Real"]
        rows_r = np.empty((steps + 1, len(reals)))
        rows_i = np.empty((steps + 1, len(integers)), dtype=np.int64)
        input_refs = {n: self.variable(n).valueReference for n in inputs}
        inst, seconds = self.instance, 0.0
        read = _Reader(inst.slave, reals, integers)

        # Communication points as fmpy's simulate_fmu computes them (start + k * interval),
        # so that the same point gives the same bits through either master.
        times = start_time + output_interval * np.arange(steps + 1)

        def collect(rows):
            series = {"time": times[:rows]}
            series.update({n: rows_r[:rows, j] for j, n in enumerate(real_names)})
            series.update({n: rows_i[:rows, j] for j, n in enumerate(integer_names)})
            return series

        read(rows_r[0], rows_i[0])
        before = len(inst.messages)
        for k in range(steps):
            t, h = float(times[k]), float(times[k + 1] - times[k])
            for name, profile in inputs.items():
                ref = input_refs[name]
                inst.setReal([ref], [profile.value(t)])
                inst.setRealInputDerivatives([ref], [1], [profile.slope(t)])
            tic = time.perf_counter()
            try:
                inst.doStep(t, h)
            except FMICallException as e:
                raise self._failure(f"doStep to t = {times[k + 1]:.9g}", e, before, "step",
                                    collect(k + 1)) from None
            seconds += time.perf_counter() - tic
            read(rows_r[k + 1], rows_i[k + 1])
        return collect(steps + 1), seconds


# --- one FMU archive rewritten ----------------------------------------------------------------

def configured_copy(fmu_path, values: dict) -> bytes:
    """The FMU's archive with `values` as its start values: in resources/start_values.txt,
    which the FMU reads at instantiation and returns to at fmi2Reset (fmu_src/
    resource_start_values.hpp), and in its modelDescription's start attributes, so that an
    importer gets them whether it applies start values (SSP tools, the ssv binding) or not
    (fmpy 0.3.32's simulate_ssp).

    FMI 3.0 (ContactBody_fmi3.fmu): the same, and a new nx also sets edge_nodes' start to
    nx + 1, a mesh to its number of contact nodes (the FMU itself counts them: `mesh` is a
    structural parameter that sets edge_nodes), so that an importer that sizes the edge arrays
    from the modelDescription (fmpy does) records that many values.

    A `mesh` that names a file goes into the copy's resources/ and is named there by its file
    name alone (the FMU looks for a relative mesh in its resources): the copy carries its body.
    Strings are written as they are, numbers as Python writes them."""
    import xml.etree.ElementTree as ET
    values = dict(values)
    edge_nodes = None
    if values.get("mesh") and _is_fmi3(fmu_path):
        edge_nodes = contact_nodes(fmu_path, values["mesh"])
    carried = {}
    if values.get("mesh") and pathlib.Path(values["mesh"]).is_file():
        mesh = pathlib.Path(values["mesh"])
        carried[f"resources/{mesh.name}"] = mesh.read_bytes()
        values["mesh"] = mesh.name
    text = lambda value: value if isinstance(value, str) else repr(value)
    out = io.BytesIO()
    with zipfile.ZipFile(fmu_path) as src, zipfile.ZipFile(out, "w") as dst:
        for info in src.infolist():
            data = src.read(info)
            if info.filename == "modelDescription.xml":
                root = ET.fromstring(data)
                starts = dict(values)
                if root.get("fmiVersion", "").startswith("3") and "nx" in values:
                    starts["edge_nodes"] = int(values["nx"]) + 1
                if edge_nodes is not None:
                    starts["edge_nodes"] = edge_nodes
                for v in root.find("ModelVariables"):
                    if v.get("name") not in starts:
                        continue
                    # FMI 2.0: the typed child of ScalarVariable; FMI 3.0: the element itself,
                    # or its <Start value=...> for Strings.
                    typed = next(iter(v)) if v.tag == "ScalarVariable" else v
                    start = typed.find("Start")
                    (typed if start is None else start).set(
                        "start" if start is None else "value", text(starts[v.get("name")]))
                data = ET.tostring(root, encoding="UTF-8", xml_declaration=True)
            dst.writestr(info, data)
        dst.writestr("resources/start_values.txt", "".join(
            f"{name} = {text(value)}\n" for name, value in values.items()))
        for name, data in carried.items():
            dst.writestr(name, data)
    return out.getvalue()


def _is_fmi3(fmu_path):
    with zipfile.ZipFile(fmu_path) as z:
        return b'fmiVersion="3' in z.read("modelDescription.xml")


def contact_nodes(fmu_path, mesh):
    """How many contact nodes the mesh file `mesh` has, as the FMI 3.0 FMU counts them: set in
    Configuration Mode, `mesh` sets the structural parameter edge_nodes. (A file the FMU cannot
    read leaves edge_nodes at nx + 1; initialization then refuses the file, saying why.)"""
    import fmpy
    from fmpy.fmi3 import FMU3Slave
    md = fmpy.read_model_description(str(fmu_path))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    with tempfile.TemporaryDirectory() as tmp:
        slave = FMU3Slave(guid=md.guid, unzipDirectory=fmpy.extract(str(fmu_path), tmp),
                          modelIdentifier=md.coSimulation.modelIdentifier, instanceName="count")
        slave.instantiate()
        try:
            slave.enterConfigurationMode()
            slave.setString([vr["mesh"]], [str(pathlib.Path(mesh).resolve())])
            count = slave.getUInt64([vr["edge_nodes"]])[0]
        finally:
            slave.freeInstance()
    return int(count)
