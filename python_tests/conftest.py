"""Shared fixtures: the built FMU, its extracted copy, and low-level instances that record
every log message."""
import ctypes
import itertools
import os
import pathlib
import shutil
import tempfile

import fmpy
import pytest
from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
from fmpy.logging import addLoggerProxy

ROOT = pathlib.Path(__file__).resolve().parents[1]
# CONTACTBODY_FMU points the suite at another build (the sanitizer job's).
FMU = pathlib.Path(os.environ.get("CONTACTBODY_FMU", ROOT / "build" / "ContactBody.fmu"))
SANITIZED = os.environ.get("CONTACTBODY_SANITIZED") == "1"


@pytest.fixture(scope="session")
def fmu_path():
    assert FMU.exists(), "build the FMU first (scripts/setup.sh)"
    return str(FMU)


@pytest.fixture(scope="session")
def model_description(fmu_path):
    return fmpy.read_model_description(fmu_path)


@pytest.fixture(scope="session")
def unzipped(fmu_path):
    directory = tempfile.mkdtemp(prefix="ContactBody_")
    fmpy.extract(fmu_path, directory)
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


@pytest.fixture(scope="session")
def vr(model_description):
    return {v.name: v.valueReference for v in model_description.modelVariables}


# fmpy's native logger proxy (which formats the variadic message) holds one Python logger
# for the whole process: messages are routed to their instance by instance name.
_messages_by_instance = {}


def _log(_env, name, status, category, message):
    _messages_by_instance.setdefault(name.decode(), []).append(
        (status, category.decode(), message.decode()))


_logger = fmi2CallbackLoggerTYPE(_log)
_serial = itertools.count()


class Instance:
    """An FMU2Slave whose log messages are kept in .messages as (status, category, text)."""

    def __init__(self, model_description, unzipped, name="instance"):
        self.name = f"{name}#{next(_serial)}"
        self.messages = _messages_by_instance.setdefault(self.name, [])
        self.slave = FMU2Slave(guid=model_description.guid, unzipDirectory=unzipped,
                               modelIdentifier=model_description.coSimulation.modelIdentifier,
                               instanceName=self.name)
        self.callbacks = fmi2CallbackFunctions()
        self.callbacks.logger = _logger
        addLoggerProxy(ctypes.byref(self.callbacks))
        self.slave.instantiate(callbacks=self.callbacks)

    def __getattr__(self, name):
        return getattr(self.slave, name)

    def text(self):
        return "\n".join(m[2] for m in self.messages)

    def close(self):
        self.slave.freeInstance()


@pytest.fixture
def instance(model_description, unzipped):
    inst = Instance(model_description, unzipped)
    yield inst
    inst.close()
