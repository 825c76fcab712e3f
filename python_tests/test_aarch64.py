"""The aarch64 Linux binary, run under user-mode emulation (Debian's qemu-user with the aarch64
loader of libc6-arm64-cross): the project's FMI host (tests_cpp/state_host.cpp), built for each
platform, runs the paper's scene and the damped sliding scene on the binary that each FMU
carries, and every output after every step and the final serialized state equal linux64's bit
for bit. (scripts/test.sh runs this file as the aarch64-linux row's job of platforms.json.)"""
import pathlib
import shutil
import subprocess
import time
import zipfile

import fmpy
import pytest
from elftools.elf.elffile import ELFFile

from conftest import FMU, PLATFORM, ROOT

pytestmark = pytest.mark.skipif(PLATFORM != "aarch64-linux",
                                reason="the aarch64 job's (scripts/test.sh, platforms.json)")

HOSTS = {"linux64": ROOT / "build" / "linux64" / "state_host",
         "aarch64-linux": ROOT / "build" / "aarch64-linux" / "state_host"}
EMULATOR = ["qemu-aarch64", "-L", "/usr/aarch64-linux-gnu"]
SCENES = {"paper": {}, "damped sliding": {"friction_coefficient": 0.3, "damping_stiffness": 4e-6}}
STEPS, STEP = 200, 1e-4  # the paper's 0.02 s


@pytest.fixture(scope="module")
def description():
    return fmpy.read_model_description(str(FMU))


def library(fmu, folder, tmp_path):
    """The platform's binary, taken from the FMU as users get it."""
    with zipfile.ZipFile(fmu) as z:
        data = z.read(f"binaries/{folder}/ContactBody.so")
    path = tmp_path / folder / "ContactBody.so"
    path.parent.mkdir(parents=True)
    path.write_bytes(data)
    return path


def run(platform, binary, guid, settings, outputs, tmp_path):
    """The host on `platform` (aarch64 under qemu): its outputs file and state, and the time."""
    args = []
    for vr, value in settings:
        args += ["--real", f"{vr}={value!r}"]
    out, state = tmp_path / f"{platform}.out", tmp_path / f"{platform}.state"
    command = [str(HOSTS[platform]), *args, str(binary), guid, "-", "0", str(STEPS), repr(STEP),
               str(out), str(state), *map(str, outputs)]
    if platform == "aarch64-linux":
        command = EMULATOR + command
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    return out.read_bytes(), state.read_bytes(), time.perf_counter() - start


def test_the_host_and_the_binary_are_aarch64():
    assert shutil.which("qemu-aarch64"), "scripts/setup.sh installs qemu-user (platforms.json)"
    assert pathlib.Path("/usr/aarch64-linux-gnu/lib/ld-linux-aarch64.so.1").exists()
    with open(HOSTS["aarch64-linux"], "rb") as f:
        assert ELFFile(f)["e_machine"] == "EM_AARCH64"


def test_both_fmus_carry_the_same_aarch64_binary(tmp_path):
    """ContactBody.fmu (FMI 2.0) and ContactBody_fmi3.fmu hold one aarch64 library, in the
    folder FMI 3.0 names aarch64-linux (FMI 2.0 has no name for it: docs/building.md)."""
    two = library(FMU, "aarch64-linux", tmp_path / "fmi2")
    three = library(FMU.with_name("ContactBody_fmi3.fmu"), "aarch64-linux", tmp_path / "fmi3")
    assert two.read_bytes() == three.read_bytes()
    with open(two, "rb") as f:
        assert ELFFile(f)["e_machine"] == "EM_AARCH64"


@pytest.mark.parametrize("scene", SCENES)
def test_aarch64_equals_linux64_bit_for_bit(scene, description, tmp_path):
    vr = {v.name: v.valueReference for v in description.modelVariables}
    outputs = [v.valueReference for v in description.modelVariables
               if v.causality == "output" and v.type == "Real"]
    settings = [(vr[name], value) for name, value in SCENES[scene].items()]
    results = {}
    for platform in ("linux64", "aarch64-linux"):
        binary = library(FMU, platform, tmp_path)
        results[platform] = run(platform, binary, description.guid, settings, outputs, tmp_path)
    (x86_out, x86_state, x86_time), (arm_out, arm_state, arm_time) = results.values()
    lines = x86_out.decode().splitlines()
    assert len(lines) == STEPS and len(lines[0].split()) == len(outputs) >= 15
    assert len(set(lines)) > STEPS // 2  # the scene moves: the comparison compares something
    assert arm_out == x86_out, next(f"step {k}: {a} against {b}" for k, (a, b) in enumerate(
        zip(arm_out.decode().splitlines(), lines)) if a != b)
    assert arm_state == x86_state  # u, v, the works, the caches: the whole state
    print(f"{scene}: {STEPS} steps, linux64 {x86_time:.2f} s, aarch64 under qemu {arm_time:.2f} s")
