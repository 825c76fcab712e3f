"""The win64 binary, run under wine. scripts/test.sh's Windows job runs this file with
CONTACTBODY_PLATFORM=win64 (conftest: the fixtures are then a copy of the FMU that holds only
binaries/win64, driven through fmpy's remoting), together with the state-machine and argument
tests of test_bad_input.py, the energy balance of test_energy_balance.py and the paper scene
against the FMU before the portable build of test_portable.py."""
import pathlib
import subprocess

import fmpy
import numpy as np
import pytest
from fmpy.fmi2 import FMU2Slave

from conftest import FMU, PLATFORM, ROOT, extract_for, fastest_kernels_of_this_cpu
from test_portable import SCENES, scene_outputs

pytestmark = pytest.mark.skipif(PLATFORM != "win64", reason="the Windows job's (scripts/test.sh)")
STATE_HOST = ROOT / "build" / "win64" / "state_host.exe"


@pytest.fixture(scope="module")
def linux_copy():
    return extract_for("linux64")


def test_the_windows_copy_holds_only_the_win64_binary(unzipped):
    binaries = pathlib.Path(unzipped) / "binaries"
    assert (binaries / "win64" / "ContactBody.dll").is_file()
    # fmpy's remoting client, which starts wine, stands where a linux64 binary would
    client = (binaries / "linux64" / "ContactBody.so").read_bytes()
    assert client == (pathlib.Path(fmpy.__file__).parent / "remoting" / "linux64" /
                      "client_tcp.so").read_bytes()


@pytest.mark.parametrize("scene", SCENES)
def test_scenes_are_bit_identical_to_linux(unzipped, linux_copy, scene):
    """The paper's scene and the METIS scene (its ordering draws GKlib's random numbers,
    which do not depend on the C library)."""
    assert scene_outputs(unzipped, scene) == scene_outputs(linux_copy, scene)


@pytest.mark.parametrize("variant", [0, 1, 2, 3, 4])
def test_every_variant_is_bit_identical_to_linux(unzipped, linux_copy, variant):
    run = dict(stop_time=2e-3, output_interval=1e-4,
               start_values={"mass_matrix": variant, "friction_coefficient": 0.3,
                             "damping_stiffness": 4e-6, "top_control": variant % 2})
    assert_same_bits(fmpy.simulate_fmu(unzipped, **run), fmpy.simulate_fmu(linux_copy, **run))


@pytest.mark.parametrize("modes", [20, 400])
def test_the_reduced_body_is_bit_identical_to_linux(unzipped, linux_copy, modes):
    """The reduced body (dense Eigen products, the Lanczos eigensolver at 20 modes of the
    840-dof body, the dense eigensolver at 400) computes the same bits on both platforms."""
    run = dict(stop_time=2e-3, output_interval=1e-4,
               start_values={"modes": modes, "friction_coefficient": 0.3,
                             "damping_stiffness": 4e-6})
    assert_same_bits(fmpy.simulate_fmu(unzipped, **run), fmpy.simulate_fmu(linux_copy, **run))


def test_a_gmsh_mesh_in_a_non_ascii_folder_is_read_alike(unzipped, linux_copy, tmp_path):
    """The mesh reader on Windows (C stdio through UTF-16 paths, from_chars): a Gmsh plate
    with a hole in a folder whose name is not ASCII gives linux64's bits."""
    from contactbody import meshes
    path = meshes.plate_with_hole(tmp_path / "maillé ü" / "hole.msh", size=0.01)
    results = []
    for fmu, name in ((unzipped, f"Z:{path}"), (linux_copy, str(path))):
        results.append(fmpy.simulate_fmu(fmu, stop_time=2e-3, output_interval=1e-4, start_values={
            "mesh": name, "friction_coefficient": 0.3, "damping_stiffness": 4e-6}))
    assert results[0]["normal_force"].max() > 0
    assert_same_bits(*results)


def test_result_files_in_a_new_non_ascii_folder_equal_linux(unzipped, linux_copy, tmp_path):
    """Field and edge output through solver/util/c_file.hpp's Windows side (UTF-16 paths): a first
    run makes the folder, whose name is not ASCII, and its parent; a second run into it replaces
    every file and removes a stale snapshot. The DLL writes the bytes linux64 writes."""
    written = {}
    for name, fmu in (("win64", unzipped), ("linux64", linux_copy)):
        folder = tmp_path / name / "résultats ü" / "nested"
        directory = f"Z:{folder}" if name == "win64" else str(folder)  # wine's Z: is /
        run = dict(stop_time=1e-3, output_interval=1e-4,
                   start_values={"result_directory": directory, "field_output_interval": 2e-4,
                                 "edge_output_interval": 1e-4})
        fmpy.simulate_fmu(fmu, **run)
        assert (folder / "contactbody_000000.vtu").is_file(), sorted(tmp_path.rglob("*"))
        (folder / "contactbody_000099.vtu").write_text("a longer earlier run's")
        fmpy.simulate_fmu(fmu, **run)
        written[name] = {p.name: p.read_bytes() for p in folder.iterdir()}
    assert "contactbody_000099.vtu" not in written["win64"]
    assert {"contactbody_edge.npy", "contactbody.pvd", "contactbody_000005.vtu"} <= set(written["win64"])
    assert written["win64"] == written["linux64"]


def assert_same_bits(windows, linux):
    for name in linux.dtype.names:
        assert [float(x).hex() for x in windows[name]] == [float(x).hex() for x in linux[name]], name


def linux_instance(directory, model_description):
    inst = FMU2Slave(guid=model_description.guid, unzipDirectory=directory,
                     modelIdentifier="ContactBody", instanceName="linux")
    inst.instantiate()
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.exitInitializationMode()
    return inst


def serialized(inst):
    state = inst.getFMUState()
    data = inst.serializeFMUState(state)
    inst.freeFMUState(state)
    return bytes(data)


def state_host(directory, guid, state, t0, steps, h, refs, tmp_path):
    """state_host.exe under wine: restore `state`, take the steps; the finished process and
    the paths of its outputs and of its new state."""
    state_in, outputs, state_out = (tmp_path / n for n in ("in.bin", "out.txt", "out.bin"))
    state_in.write_bytes(state)
    dll = pathlib.Path(directory) / "binaries" / "win64" / "ContactBody.dll"
    windows = lambda p: "Z:" + str(p)  # wine's drive for /
    out = subprocess.run(["wine64", str(STATE_HOST), windows(dll), guid, windows(state_in),
                          repr(t0), str(steps), repr(h), windows(outputs), windows(state_out),
                          *map(str, refs)], capture_output=True, text=True, timeout=300)
    return out, outputs, state_out


def run_on_windows(directory, guid, state, t0, steps, h, refs, tmp_path):
    """The outputs after each step and the new state, serialized."""
    out, outputs, state_out = state_host(directory, guid, state, t0, steps, h, refs, tmp_path)
    assert out.returncode == 0, out.stderr[-3000:]
    rows = [[float.fromhex(x) for x in line.split()] for line in outputs.read_text().splitlines()]
    return rows, state_out.read_bytes()


def test_state_serialized_on_linux_replays_on_windows_and_back(unzipped, linux_copy, tmp_path):
    """Linux steps to t1 and serializes; Windows restores that state and steps to t2; Linux
    restores Windows' state at t2 and steps to t3. Every output on the way equals the run
    that stayed on Linux, bit for bit, and so do the serialized states."""
    assert STATE_HOST.is_file(), "the win64 build makes state_host.exe (CMakeLists.txt)"
    md = fmpy.read_model_description(linux_copy)
    refs = [v.valueReference for v in md.modelVariables
            if v.causality == "output" and v.type == "Real"]
    h, steps = 1e-4, 10
    reference = linux_instance(linux_copy, md)
    rows = []
    for k in range(3 * steps):
        reference.doStep(k * h, h)
        rows.append(reference.getReal(refs))
        if k + 1 == steps:
            at_t1 = serialized(reference)
        if k + 1 == 2 * steps:
            at_t2 = serialized(reference)
    reference.terminate()
    reference.freeInstance()

    windows_rows, windows_t2 = run_on_windows(unzipped, md.guid, at_t1, steps * h, steps, h,
                                              refs, tmp_path)
    assert windows_rows == rows[steps:2 * steps]
    assert windows_t2 == at_t2

    back = linux_instance(linux_copy, md)
    state = back.deserializeFMUState(windows_t2)
    back.setFMUState(state)
    back.freeFMUState(state)
    for k in range(2 * steps, 3 * steps):
        back.doStep(k * h, h)
        assert back.getReal(refs) == rows[k]
    back.terminate()
    back.freeInstance()


def test_a_state_from_linux_is_refused_on_windows_when_truncated(unzipped, linux_copy, tmp_path):
    """The bytes are checked there too: a cut state is an error, not a crash."""
    md = fmpy.read_model_description(linux_copy)
    inst = linux_instance(linux_copy, md)
    inst.doStep(0, 1e-4)
    state = serialized(inst)
    inst.terminate()
    inst.freeInstance()
    out, _, _ = state_host(unzipped, md.guid, state[: len(state) // 2], 1e-4, 1, 1e-4, [100],
                           tmp_path)
    assert out.returncode == 1 and "fmi2DeSerializeFMUstate failed" in out.stderr, out.stderr
    assert "fmi2DeSerializeFMUstate" in out.stderr.split("state_host:")[0]  # the FMU logged why


@pytest.mark.parametrize("name", ["BeltDrive", "Press"])
def test_companion_fmus_are_bit_identical_to_linux(name):
    """The companions of the system models are built the same way, so the SSP and the
    container FMU can run on Windows too."""
    fmu = FMU.with_name(f"{name}.fmu")
    run = dict(stop_time=0.01, output_interval=1e-4)
    linux = fmpy.simulate_fmu(extract_for("linux64", fmu), **run)
    windows = fmpy.simulate_fmu(extract_for("win64", fmu), **run)
    assert len(linux) == 101
    assert_same_bits(windows, linux)


FMI3_HOST = ROOT / "build" / "win64" / "fmi3_host.exe"


def test_fmi3_layer_on_windows_continues_a_linux_state_bit_for_bit(tmp_path):
    """The FMI 3.0 entry points of the win64 binary (fmpy's remoting carries FMI 2.0 only, so
    fmi3_host.exe calls them under wine): a state serialized on Linux continues on Windows,
    with scalars and edge arrays equal to the Linux run bit for bit, on the default mesh and
    with nx = 10 set in Configuration Mode."""
    from fmpy.fmi3 import FMU3Slave
    fmu3 = FMU.with_name("ContactBody_fmi3.fmu")
    linux3 = extract_for("linux64", fmu3)
    windows3 = extract_for("linux64", fmu3)  # the win64 DLL is in it, wine loads it
    md3 = fmpy.read_model_description(linux3)
    vr = {v.name: v.valueReference for v in md3.modelVariables}
    h, steps = 1e-4, 8
    for nx in (20, 10):
        names = ["energy", "normal_force", "friction_force", "edge_pressure", "edge_friction",
                 "edge_gap"]
        counts = [nx + 1 if n.startswith("edge_") else 1 for n in names]
        reference = FMU3Slave(guid=md3.guid, unzipDirectory=linux3, modelIdentifier="ContactBody",
                              instanceName="linux")
        reference.instantiate()
        reference.enterConfigurationMode()
        reference.setUInt64([vr["nx"]], [nx])
        reference.exitConfigurationMode()
        reference.enterInitializationMode(startTime=0)
        reference.exitInitializationMode()
        rows = []
        for k in range(2 * steps):
            reference.doStep(k * h, h)
            rows.append(reference.getFloat64([vr[n] for n in names], sum(counts)))
            if k + 1 == steps:
                state = reference.getFMUState()
                at_t1 = bytes(reference.serializeFMUState(state))
                reference.freeFMUState(state)
        reference.terminate()
        reference.freeInstance()

        state_in, outputs, state_out = (tmp_path / f"{nx}_{n}" for n in ("in", "out", "state"))
        state_in.write_bytes(at_t1)
        dll = pathlib.Path(windows3) / "binaries" / "x86_64-windows" / "ContactBody.dll"
        windows = lambda p: "Z:" + str(p)  # wine's drive for /
        out = subprocess.run(["wine64", str(FMI3_HOST), windows(dll), md3.guid,
                              "-" if nx == 20 else str(nx), windows(state_in), repr(steps * h),
                              str(steps), repr(h), windows(outputs), windows(state_out),
                              *(f"{vr[n]}:{c}" for n, c in zip(names, counts))],
                             capture_output=True, text=True, timeout=300)
        assert out.returncode == 0, out.stderr[-3000:]
        got = [[float.fromhex(x) for x in line.split()] for line in outputs.read_text().splitlines()]
        assert got == rows[steps:], nx


@pytest.mark.parametrize("values", [
    {"mass_matrix": 1},
    {"mass_matrix": 4, "stribeck_velocity": 5.0, "static_friction_ratio": 1.5, "viscous_friction": 0.01},
    {"modes": 60, "reduced_edge": 2},
], ids=["isotropic_friction", "slip_rate_law", "reduced_body"])
def test_the_3d_model_is_bit_identical_to_linux(values):
    """ContactBody3D's win64 binary (the tetrahedral kernels, the disc friction, the dense
    eigensolver of the reduced body): the default block sliding along (12, 16) m/s, 1 ms, bit for
    bit. With the slip-rate law, to round-off only: its exp is the C library's, msvcrt's on
    Windows and zig's compiler_rt's on Linux (cmake/fmu_binaries.cmake), which differ in the last
    bit (measured: the energy at 1e-4 s, 0x1.010140d6f13ffp-5 against ...400p-5)."""
    fmu3d = FMU.with_name("ContactBody3D.fmu")
    run = dict(stop_time=1e-3, output_interval=1e-4,
               start_values={"friction_coefficient": 0.5, "foundation_velocity": 12.0,
                             "foundation_velocity_z": 16.0, "damping_stiffness": 2e-6, **values})
    windows, linux = extract_for("win64", fmu3d), extract_for("linux64", fmu3d)
    a, b = fmpy.simulate_fmu(windows, **run), fmpy.simulate_fmu(linux, **run)
    if "stribeck_velocity" not in values:
        assert_same_bits(a, b)
        return
    # The physical outputs (max_penetration is round-off itself, 1e-20 m here; the counts of
    # Newton iterations may differ by one where a residual sits at the tolerance).
    for name in ["energy", "kinetic_energy", "strain_energy", "friction_work", "clamp_work",
                 "normal_contact_work", "friction_dissipation", "foundation_work", "damping_work",
                 "normal_force", "friction_force", "friction_force_z", "top_reaction_x",
                 "top_reaction_y", "top_reaction_z"]:
        scale = np.abs(b[name]).max()
        assert np.abs(a[name] - b[name]).max() <= 1e-10 * scale, name


def test_the_fast_kernels_run_on_windows_as_on_linux(tmp_path):
    """The supernodal factor's fastest kernels (x86-64-v3 or x86-64-v4, built by MinGW's gcc into
    the DLL, whose stack Windows aligns to 16 bytes only) on a 2.7k-node hemisphere pressed from
    the static start (its factor is supernodal): the outputs agree with linux64's fast kernels
    to 1e-10 relative (the two compilers' sums may round apart), and they are not the baseline
    kernels' bits, which are the same on both platforms (fmpy's remoting refuses
    fmi2SetDebugLogging, so the log cannot say which set ran)."""
    from contactbody import meshes
    mesh = meshes.hemisphere(tmp_path / "hemisphere.msh", radius=0.05, contact_size=5e-4,
                             far_size=1e-2, fine_distance=0.0045, refine_distance=0.025,
                             contact_angle=25.0)
    fmu3d = FMU.with_name("ContactBody3D.fmu")
    outputs = ["normal_force", "strain_energy", "kinetic_energy", "top_reaction_y", "energy"]
    runs = {}
    for name, path, baseline in (("win64", f"Z:{mesh}", 0), ("linux64", str(mesh), 0),
                                 ("linux64", str(mesh), 1)):
        runs[name, baseline] = fmpy.simulate_fmu(
            extract_for(name, fmu3d), stop_time=3e-4, output_interval=1e-4, output=outputs,
            start_values={"mesh": path, "friction_coefficient": 0.0, "initial_state": 1,
                          "top_displacement": -2e-4, "internal_step": 1e-6, "damping_stiffness": 4e-6,
                          "baseline_kernels": baseline})
    windows, linux = runs["win64", 0], runs["linux64", 0]
    for name in outputs:
        scale = np.abs(linux["energy" if name == "kinetic_energy" else name]).max()
        assert scale > 0, name
        assert np.abs(windows[name] - linux[name]).max() <= 1e-10 * scale, (name, np.abs(windows[name] - linux[name]).max() / scale)
    if fastest_kernels_of_this_cpu() != "baseline":
        assert any(np.any(windows[n] != runs["linux64", 1][n]) for n in outputs), "win64 ran the baseline kernels"
