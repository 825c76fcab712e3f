"""Shared fixtures: the built FMU, its extracted copy, and low-level instances that record
every log message."""
import os
import pathlib
import shutil
import tempfile

import fmpy
import pytest

# An fmpy FMU2Slave that keeps its log messages in .messages (status, category, text).
from contactbody.fmu import Instance  # noqa: F401

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


@pytest.fixture
def instance(model_description, unzipped):
    inst = Instance(model_description, unzipped)
    yield inst
    inst.close()
