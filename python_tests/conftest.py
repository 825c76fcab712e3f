"""Shared fixtures: the built FMU, its extracted copy, and low-level instances that record
every log message."""
import atexit
import ctypes
import os
import pathlib
import shutil
import socket
import subprocess
import tempfile
import time

import fmpy
import pytest

from contactbody.tools import platforms
from contactbody.tools.cpu import fastest_supernodal_kernels as fastest_kernels_of_this_cpu  # noqa: F401

# An fmpy FMU2Slave that keeps its log messages in .messages (status, category, text).
from contactbody.fmu import Instance  # noqa: F401

ROOT = pathlib.Path(__file__).resolve().parents[1]
# CONTACTBODY_FMU points the suite at another build (the sanitizer job's).
FMU = pathlib.Path(os.environ.get("CONTACTBODY_FMU", ROOT / "build" / "ContactBody.fmu"))
SANITIZED = os.environ.get("CONTACTBODY_SANITIZED") == "1"
# CONTACTBODY_PLATFORM=win64 (scripts/test.sh's Windows job): the fixtures below give a copy of
# the FMU that holds only binaries/win64, run under wine through fmpy's remoting.
PLATFORM = os.environ.get("CONTACTBODY_PLATFORM", "linux64")
assert PLATFORM in platforms.names(), f"CONTACTBODY_PLATFORM={PLATFORM} is not in platforms.json"
if PLATFORM == "win64":
    # fmpy starts `wine64` from PATH; ours (scripts/wine/wine64 says why) keeps the server up.
    os.environ["PATH"] = f"{ROOT / 'scripts' / 'wine'}{os.pathsep}{os.environ['PATH']}"
    os.environ.setdefault("WINEDEBUG", "-all")
    # wineserver ends itself a moment after the last wine process; an instance started as it
    # ends waited up to 2.5 s for its server here (0.5 s otherwise). CI once saw fmpy's client
    # give up after its 10 s ("Failed to instantiate model"), most likely in that race. One
    # persistent wineserver serves the session instead.
    _prefix = pathlib.Path(os.environ.get("WINEPREFIX", pathlib.Path.home() / ".wine"))
    _prefix.mkdir(parents=True, exist_ok=True)  # wine fills an empty prefix on its first run
    subprocess.run(["/usr/lib/wine/wineserver", "--persistent"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    atexit.register(subprocess.run, ["/usr/lib/wine/wineserver", "--kill"],
                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def not_through_remoting(why):
    """Skips a test in the Windows job where fmpy's remoting, not the FMU, cannot carry it."""
    return pytest.mark.skipif(PLATFORM == "win64", reason=f"fmpy's remoting {why}")


# fmpy's remoting client does not survive being unloaded: after two simulate_fmu runs of
# BeltDrive's win64 copy the Python process crashed in its own allocations (a client thread or
# handler outlives dlclose; under valgrind the timing hides it). Held here, it stays loaded.
_REMOTING_CLIENTS = []


def _remoting_port_listens():
    """Whether anything listens on fmpy's remoting port (rpclib's 8080), read from /proc."""
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        for line in pathlib.Path(table).read_text().splitlines()[1:]:
            fields = line.split()
            if fields[1].endswith(":1F90") and fields[3] == "0A":  # 0A: LISTEN
                return True
    return False


if PLATFORM == "win64":
    # fmpy's remoting client connects to "localhost". Where that name does not resolve (a bare
    # debootstrap chroot has no /etc/hosts) every remoting test failed with fmpy's "Failed to
    # instantiate model" while the server listened: say so once instead.
    try:
        socket.getaddrinfo("localhost", 8080, type=socket.SOCK_STREAM)
    except socket.gaierror as error:
        raise RuntimeError(f"the Windows job needs 'localhost' to resolve ({error}): fmpy's "
                           "remoting client connects to its wine server there; add "
                           "'127.0.0.1 localhost' to /etc/hosts") from None

    # fmpy's client kills its wine server when the instance is freed, but wineserver closes
    # the server's listening socket a moment later: a next instance's client that connects in
    # between reaches the dead server and waits forever (seen in CI). Wait for the port.
    import fmpy.fmi2

    _free_instance = fmpy.fmi2._FMU2.freeInstance

    def _free_instance_and_wait(self):
        _free_instance(self)
        deadline = time.monotonic() + 30
        while _remoting_port_listens():
            assert time.monotonic() < deadline, "fmpy's remoting server did not stop"
            time.sleep(0.02)

    fmpy.fmi2._FMU2.freeInstance = _free_instance_and_wait


def extract_for(platform, fmu=FMU):
    """The FMU extracted to a new folder; for win64 with binaries/linux64 replaced by fmpy's
    remoting client, which runs binaries/win64 in a wine process."""
    assert fmu.exists(), "build the FMU first (scripts/setup.sh)"
    directory = tempfile.mkdtemp(prefix=f"{fmu.stem}_{platform}_")
    fmpy.extract(str(fmu), directory)
    if platform == "win64":
        from fmpy.util import add_remoting
        shutil.rmtree(pathlib.Path(directory) / "binaries" / "linux64")
        add_remoting(directory, host_platform="linux64", remote_platform="win64")
        _REMOTING_CLIENTS.append(ctypes.CDLL(str(pathlib.Path(directory) / "binaries" /
                                                 "linux64" / f"{fmu.stem}.so")))
    return directory


@pytest.fixture(scope="session")
def fmu_path(unzipped):
    """What fmpy.simulate_fmu runs: the .fmu, or in the Windows job its win64 folder."""
    return str(FMU) if PLATFORM == "linux64" else unzipped


@pytest.fixture(scope="session")
def model_description(fmu_path):
    return fmpy.read_model_description(fmu_path)


@pytest.fixture(scope="session")
def unzipped():
    directory = extract_for(PLATFORM)
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


def fmu_log(start_values, unzipped):
    """(raised error or None, every log message) of an initialization and a first step with
    these values on the extracted FMU `unzipped` (its own model description), on an instance
    of our own that is freed whatever happens."""
    from fmpy.fmi1 import FMICallException
    description = fmpy.read_model_description(unzipped)
    inst = Instance(description, unzipped, "mesh_log")
    try:
        inst.setDebugLogging(True, [])
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.set_values(start_values)
        try:
            inst.exitInitializationMode()
            inst.doStep(0, 1e-5)
            error = None
        except FMICallException as e:
            error = e
        return error, [m[2] for m in inst.messages]
    finally:
        inst.close()


def refused(start_values, unzipped, *needles):
    """The start fails, and its log holds every needle; returns the log."""
    error, messages = fmu_log(start_values, unzipped)
    assert error is not None, "initialization went through"
    text = "\n".join(messages)
    for needle in needles:
        assert needle in text, text[-2000:]
    return text
