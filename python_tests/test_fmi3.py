"""The same body as an FMI 3.0 Co-Simulation FMU (build/ContactBody_fmi3.fmu), from
the same variable table and the same binary, with the contact edge as arrays sized by the
structural parameter edge_nodes = nx + 1."""
import ctypes
import pathlib
import shutil
import zipfile
from xml.etree import ElementTree

import fmpy
import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from conftest import FMU, PLATFORM, SANITIZED, extract_for
from contactbody.tools import macho, platforms

pytestmark = pytest.mark.skipif(PLATFORM != "linux64", reason="the FMI 3.0 FMU is tested on linux64")

FMU3 = FMU.with_name("ContactBody_fmi3.fmu")
H = 1e-4
ARRAYS = ["edge_x", "edge_pressure", "edge_friction", "edge_slip_velocity", "edge_gap"]
# The quick start's damped sliding (README): F = 0.2 with beta = 4e-6 s.
SCENES = {"default": {},
          "damped sliding": {"friction_coefficient": 0.2, "damping_stiffness": 4e-6}}


@pytest.fixture(scope="module")
def md3():
    return fmpy.read_model_description(str(FMU3))


@pytest.fixture(scope="module")
def md2():
    return fmpy.read_model_description(str(FMU))


@pytest.fixture(scope="module")
def vr3(md3):
    return {v.name: v.valueReference for v in md3.modelVariables}


@pytest.fixture(scope="module")
def unzipped3():
    directory = extract_for("linux64", FMU3)
    yield directory
    shutil.rmtree(directory, ignore_errors=True)


class Instance3:
    """An fmpy FMU3Slave that keeps its log messages (status, category, text)."""

    def __init__(self, md, unzipped, name="i3"):
        self.messages = []

        def log(env, status, category, message):
            self.messages.append((status, category.decode(), message.decode()))

        self.slave = FMU3Slave(guid=md.guid, unzipDirectory=unzipped,
                               modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        # FMI 3.0: with logging off the FMU calls logMessage for nothing, errors included.
        self.slave.instantiate(loggingOn=True, logMessage=log)

    def __getattr__(self, name):
        return getattr(self.slave, name)

    def text(self):
        return "\n".join(m[2] for m in self.messages)


@pytest.fixture
def make3(md3, unzipped3):
    made = []

    def make(name="i3"):
        made.append(Instance3(md3, unzipped3, name))
        return made[-1]

    yield make
    for inst in made:
        inst.slave.freeInstance()


def edge_shares(x):
    """The boundary length each bottom node carries (half a cell at the ends)."""
    dx = np.diff(x)
    return np.concatenate([[dx[0] / 2], (dx[:-1] + dx[1:]) / 2, [dx[-1] / 2]])


def test_fmpy_validates_the_fmi3_fmu_and_it_carries_the_same_binary(tmp_path):
    assert validate_fmu(str(FMU3)) == []
    # FMI 3.0 has a folder per row; FMI 2.0 a folder per fmi2_folder (darwin64: both macOS
    # rows in one universal binary, its slices checked against FMI 3.0's in test_portable).
    rows = platforms.platforms()[:1] if SANITIZED else platforms.platforms()
    with zipfile.ZipFile(FMU) as z2, zipfile.ZipFile(FMU3) as z3:
        two = {n[len("binaries/"):] for n in z2.namelist() if n.startswith("binaries/")}
        three = {n[len("binaries/"):] for n in z3.namelist() if n.startswith("binaries/")}
        assert three == {f"{p['fmi3_tuple']}/ContactBody{p['library_suffix']}" for p in rows}
        assert two == {f"{p['fmi2_folder']}/ContactBody{p['library_suffix']}" for p in rows}
        for p in rows:
            name = f"ContactBody{p['library_suffix']}"
            fmi3_binary = z3.read(f"binaries/{p['fmi3_tuple']}/{name}")
            if [q["fmi2_folder"] for q in rows].count(p["fmi2_folder"]) == 1:
                assert z2.read(f"binaries/{p['fmi2_folder']}/{name}") == fmi3_binary, p["name"]
            else:  # its slice of the universal binary
                universal = tmp_path / f"{p['fmi2_folder']}{p['library_suffix']}"
                universal.write_bytes(z2.read(f"binaries/{p['fmi2_folder']}/{name}"))
                arch = p["static_checks"]["lipo_arch"]
                assert macho.thin(universal, arch, tmp_path).read_bytes() == fmi3_binary, p["name"]


def limits(fmu):
    """(start, min, max) of every variable, from the XML itself (fmpy skips UInt64 limits)."""
    with zipfile.ZipFile(fmu) as z:
        root = ElementTree.fromstring(z.read("modelDescription.xml"))
    out = {}
    for v in root.find("ModelVariables"):
        typed = v[0] if v.tag == "ScalarVariable" else v
        start = typed.find("Start")  # FMI 3.0 Strings: <Start value=""/>
        out[v.get("name")] = (typed.get("start") if start is None else start.get("value"),
                              typed.get("min"), typed.get("max"))
    return out


def test_one_variable_table_two_standards(md2, md3):
    """Every FMI 2.0 variable is in the FMI 3.0 FMU by the same name, reference, causality
    (structural for nx, ny and mesh), unit, start and limits, with FMI 3.0's type."""
    three = {v.name: v for v in md3.modelVariables}
    limits2, limits3 = limits(FMU), limits(FMU3)
    types = {"Real": "Float64", "Integer": "Int32", "Enumeration": "Enumeration", "String": "String"}
    for v in md2.modelVariables:
        w = three.pop(v.name)
        assert w.valueReference == v.valueReference, v.name
        structural = v.name in ("nx", "ny", "mesh")
        assert w.causality == ("structuralParameter" if structural else v.causality), v.name
        assert w.type == ("UInt64" if v.name in ("nx", "ny") else types[v.type]), v.name
        assert w.variability == v.variability and w.unit == v.unit, v.name
        assert limits3[v.name] == limits2[v.name], v.name
        assert not w.dimensions, v.name
    assert three.pop("time").causality == "independent"
    assert three.pop("edge_nodes").causality == "structuralParameter"
    assert sorted(three) == sorted(ARRAYS + ["edge_state"])
    for v in three.values():
        assert v.causality == "output" and v.shape == (21,), v.name
    assert md3.modelVariables[0].name == "time"


@pytest.mark.parametrize("scene", SCENES)
def test_every_scalar_output_equals_the_fmi2_fmus_bit_for_bit(scene, md2):
    outputs = [v.name for v in md2.modelVariables if v.causality == "output"]
    runs = [fmpy.simulate_fmu(str(f), stop_time=0.02, output_interval=H, start_values=SCENES[scene],
                              output=outputs) for f in (FMU, FMU3)]
    assert len(runs[0]) == len(runs[1]) == 201
    for name in ["time"] + outputs:
        assert runs[0][name].tobytes() == runs[1][name].tobytes(), name


def test_ramped_inputs_through_fmpy_equal_the_fmi2_fmus_bit_for_bit(md2):
    """FMI 3.0 has no input derivatives in Co-Simulation: input_interpolation = ramp works as
    in FMI 2.0. A press (top_displacement 0 -> -20 um -> 0 at 500 Hz) given to fmpy as an input
    table, ramped, gives the same outputs from both FMUs."""
    times = np.arange(0, 0.01 + H / 2, H)
    signals = np.array(list(zip(times, -20e-6 * np.sin(np.pi * 500 * times) ** 2)),
                       dtype=[("time", float), ("top_displacement", float)])
    outputs = [v.name for v in md2.modelVariables if v.causality == "output"]
    runs = [fmpy.simulate_fmu(str(f), stop_time=0.01, output_interval=H, input=signals,
                              start_values={"input_interpolation": 1, "friction_coefficient": 0.0},
                              output=outputs) for f in (FMU, FMU3)]
    assert runs[0]["top_position"].min() < -15e-6  # the press moved the top
    for name in ["time"] + outputs:
        assert runs[0][name].tobytes() == runs[1][name].tobytes(), name


@pytest.mark.parametrize("scene", SCENES)
def test_the_arrays_add_up_to_the_scalar_outputs(scene):
    """Straight from simulate_fmu's shaped columns: nx + 1 entries; node shares x densities sum
    to normal_force and friction_force to 1e-12 at every output; the states count the active
    and slipping nodes."""
    r = fmpy.simulate_fmu(str(FMU3), stop_time=0.02, output_interval=H,
                          start_values=SCENES[scene])
    for name in ARRAYS + ["edge_state"]:
        assert r[name].shape == (201, 21), name
    share = edge_shares(r["edge_x"][0])
    assert np.all(r["edge_x"] == r["edge_x"][0]) and np.isclose(r["edge_x"][0][-1], 0.1)
    for density, total in (("edge_pressure", "normal_force"), ("edge_friction", "friction_force")):
        sums = r[density] @ share
        scale = np.abs(r[total]).max()
        assert scale > 0 and np.abs(sums - r[total]).max() <= 1e-12 * scale, density
    state = r["edge_state"]
    assert set(np.unique(state)) <= {0, 1, 2} and (state == 2).any() and (state == 1).any()
    assert np.array_equal((state > 0).sum(axis=1), r["active_contact_nodes"])
    assert np.array_equal((state == 2).sum(axis=1), r["slipping_contact_nodes"])
    # Open nodes carry no force and have a gap; the others touch (to the midpoint overshoot).
    open_ = state[1:] == 0
    assert np.all(r["edge_gap"][1:][~open_] <= r["max_penetration"].max())


def test_configuration_mode_reshapes_the_arrays(make3, vr3):
    inst = make3()
    inst.enterConfigurationMode()
    inst.setUInt64([vr3["nx"]], [10])
    assert inst.getUInt64([vr3["nx"], vr3["edge_nodes"]]) == [10, 11]
    # Only structural parameters in Configuration Mode.
    with pytest.raises(FMICallException):
        inst.setFloat64([vr3["density"]], [2000.0])
    assert "density is not a structural parameter" in inst.text()
    inst.exitConfigurationMode()
    inst.enterInitializationMode(startTime=0)
    inst.exitInitializationMode()
    inst.doStep(0, H)
    x = inst.getFloat64([vr3["edge_x"]], 11)
    assert np.allclose(x, np.linspace(0, 0.1, 11))
    values = inst.getFloat64([vr3["edge_pressure"], vr3["normal_force"]], 12)
    assert np.isclose(np.dot(values[:11], edge_shares(np.array(x))), values[11], rtol=1e-12)
    assert len(inst.getInt64([vr3["edge_state"]], 11)) == 11
    with pytest.raises(FMICallException):
        inst.getFloat64([vr3["edge_pressure"]], 21)
    assert "nValues is 21, the variables hold 11" in inst.text()


def test_edge_nodes_must_be_nx_plus_one(make3, vr3):
    inst = make3()
    inst.enterConfigurationMode()
    inst.setUInt64([vr3["edge_nodes"], vr3["nx"]], [41, 40])  # either order
    inst.exitConfigurationMode()
    bad = make3("bad")
    bad.enterConfigurationMode()
    bad.setUInt64([vr3["nx"], vr3["edge_nodes"]], [10, 21])
    with pytest.raises(FMICallException):
        bad.exitConfigurationMode()
    assert "edge_nodes = 21 but nx + 1 = 11" in bad.text()
    # The same check when the importer sets them at instantiation (fmpy does) instead.
    late = make3("late")
    late.setUInt64([vr3["edge_nodes"]], [30])
    late.enterInitializationMode(startTime=0)
    with pytest.raises(FMICallException):
        late.exitInitializationMode()
    assert "edge_nodes = 30 but nx + 1 = 21" in late.text()


def read_all(inst, vr3, md3):
    """Every output: the scalars and the arrays, as bytes."""
    reals = [v.valueReference for v in md3.modelVariables
             if v.causality == "output" and v.type == "Float64" and not v.dimensions]
    ints = [v.valueReference for v in md3.modelVariables
            if v.causality == "output" and v.type == "Int32"]
    arrays = [vr3[n] for n in ARRAYS]
    return (np.array(inst.getFloat64(reals)).tobytes(), tuple(inst.getInt32(ints)),
            np.array(inst.getFloat64(arrays, 21 * len(arrays))).tobytes(),
            tuple(inst.getInt64([vr3["edge_state"]], 21)))


def test_state_save_restore_and_serialize_replay_bit_for_bit(make3, vr3, md3, model_description,
                                                          unzipped):
    def started(inst):
        inst.enterInitializationMode(startTime=0)
        inst.setFloat64([vr3["friction_coefficient"], vr3["damping_stiffness"]], [0.2, 4e-6])
        inst.exitInitializationMode()
        return inst

    def run(inst, k0, k1):
        rows = []
        for k in range(k0, k1):
            *flags, last_successful_time = inst.doStep(k * H, H)
            assert flags == [False, False, False]
            assert last_successful_time == pytest.approx((k + 1) * H, abs=1e-15)
            rows.append(read_all(inst, vr3, md3))
        return rows

    inst = started(make3())
    run(inst, 0, 5)
    saved = inst.getFMUState()
    at_save = read_all(inst, vr3, md3)
    rows = run(inst, 5, 15)
    inst.setFMUState(saved)
    assert read_all(inst, vr3, md3) == at_save  # the arrays come back with the state
    assert run(inst, 5, 15) == rows
    blob = inst.serializeFMUState(saved)
    fresh = started(make3("fresh"))
    fresh.setFMUState(fresh.deserializeFMUState(blob))
    assert read_all(fresh, vr3, md3) == at_save
    assert run(fresh, 5, 15) == rows

    # The FMI 2.0 layer writes the same bytes for the same content.
    from conftest import Instance
    two = Instance(model_description, unzipped, "fmi2")
    try:
        vr2 = {v.name: v.valueReference for v in model_description.modelVariables}
        two.setupExperiment(startTime=0)
        two.enterInitializationMode()
        two.setReal([vr2["friction_coefficient"], vr2["damping_stiffness"]], [0.2, 4e-6])
        two.exitInitializationMode()
        for k in range(5):
            two.doStep(k * H, H)
        other = two.serializeFMUstate(two.getFMUstate())
        diff = [k for k in range(28, len(blob)) if other[k] != blob[k]]
        assert len(other) == len(blob) and not diff, (diff[:10], len(diff))
    finally:
        two.close()


def test_a_failed_step_leaves_the_instance_where_fmi3_says(make3, vr3):
    """F = 5 with redistributed_both: no unique solution of a step (paper, section 6). fmi3Error
    with the cause, the state back at the step's start, then only fmi3SetFMUState (or reset)
    goes on."""
    inst = make3()
    inst.enterInitializationMode(startTime=0)
    inst.setFloat64([vr3["friction_coefficient"], vr3["min_internal_step"]], [5.0, 1e-7])
    inst.setInt64([vr3["mass_matrix"]], [2])
    inst.exitInitializationMode()
    start = inst.getFMUState()
    energy = inst.getFloat64([vr3["energy"]])
    with pytest.raises(FMICallException):
        inst.doStep(0, H)
    assert "fmi3DoStep" in inst.text() and "contact solve failed" in inst.text()
    assert inst.getFloat64([vr3["energy"]]) == energy
    with pytest.raises(FMICallException):
        inst.doStep(0, H)
    assert "fmi3DoStep: not allowed in state Error" in inst.text()
    inst.setFMUState(start)
    inst.setFloat64([vr3["friction_coefficient"]], [0.2])  # tunable
    assert inst.doStep(0, H)[3] == pytest.approx(H, abs=1e-15)


def test_refusals_name_the_function_and_the_cause(make3, vr3, md3, unzipped3):
    inst = make3()
    for call, text in [
        (lambda: inst.setFloat64([vr3["edge_pressure"]], [1.0]), "edge_pressure is an output"),
        (lambda: inst.setInt32([vr3["nx"]], [3]), "nx is of type UInt64, not Int32"),
        (lambda: inst.setUInt64([vr3["nx"]], [2**40]), "nx = 1099511627776 is out of range"),
        (lambda: inst.setUInt64([vr3["nx"]], [0]), "nx = 0 is out of range"),
        (lambda: inst.getFloat64([vr3["energy"]]), "fmi3GetFloat64: not allowed in state Instantiated"),
        (lambda: inst.doStep(0, H), "fmi3DoStep: not allowed in state Instantiated"),
        (lambda: inst.enterEventMode(), "hasEventMode is false"),
        (lambda: inst.setBoolean([1], [True]), "this FMU has no Boolean variables"),
    ]:
        with pytest.raises(FMICallException):
            call()
        assert text in inst.messages[-1][2], (text, inst.messages[-1])
    # Event mode and intermediate variables are refused at instantiation.
    slave = FMU3Slave(guid=md3.guid, unzipDirectory=unzipped3,
                      modelIdentifier="ContactBody", instanceName="events")
    messages = []
    with pytest.raises(Exception, match="Failed to instantiate"):
        slave.instantiate(eventModeUsed=True, loggingOn=True,
                          logMessage=lambda e, s, c, m: messages.append(m.decode()))
    assert "no event mode" in messages[-1]


def test_the_arrays_are_the_edge_history_record_for_record(tmp_path):
    """The FMI 3.0 arrays and the FMI 2.0 FMU's edge history file (edge_output_interval) come
    from the same edge snapshot: equal bit for bit at every output, through
    contactbody.edge.from_result."""
    from contactbody import edge
    scene = {"initial_state": 1, "foundation_velocity": 0.05, "friction_coefficient": 0.5,
             "static_friction_ratio": 2.0, "damping_stiffness": 4e-6}
    fmpy.simulate_fmu(str(FMU), stop_time=3e-3, output_interval=1e-4, output=["energy"],
                      start_values={**scene, "result_directory": str(tmp_path),
                                    "field_output_interval": 1.0, "edge_output_interval": 1e-4})
    history = edge.load(tmp_path / "contactbody_edge.npy")
    arrays = edge.from_result(fmpy.simulate_fmu(str(FMU3), stop_time=3e-3, output_interval=1e-4,
                                                start_values=scene))
    assert arrays.dtype == history.dtype and len(arrays) == len(history) == 31
    assert arrays.tobytes() == history.tobytes()
    assert (arrays["state"] == 1).any() and (arrays["state"] == 2).any()


def test_the_example_plots_the_map_from_simulate_fmu(tmp_path):
    import subprocess
    import sys
    from conftest import ROOT
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "edge_map_fmi3.py"), "--out",
                          str(tmp_path)], capture_output=True, text=True, cwd=ROOT / "examples")
    assert out.returncode == 0, out.stderr
    assert "recorded as (1001, 21)" in out.stdout and "equal active_contact_nodes at every output: True" in out.stdout
    assert (tmp_path / "edge_map_fmi3.png").stat().st_size > 10_000


def test_committed_fmi3_model_description_is_the_generated_one(unzipped3):
    from conftest import ROOT
    generated = (pathlib.Path(unzipped3) / "modelDescription.xml").read_text()
    committed = (ROOT / "modelDescription" / "modelDescription_fmi3.xml").read_text()
    assert generated == committed, ("modelDescription/modelDescription_fmi3.xml is stale: copy "
                                    "build/fmu/ContactBody_fmi3/modelDescription.xml")


def test_a_configured_copy_with_another_nx_runs_in_plain_fmpy(tmp_path):
    """fmpy sizes the arrays from the modelDescription's start of edge_nodes (it does not enter
    Configuration Mode): contactbody.fmu.configured_copy writes nx and edge_nodes = nx + 1,
    and plain simulate_fmu records 11-node arrays that add up to normal_force."""
    from contactbody.fmu import configured_copy
    copy = tmp_path / "ContactBody_fmi3_nx10.fmu"
    copy.write_bytes(configured_copy(FMU3, {"nx": 10, "friction_coefficient": 0.2}))
    assert validate_fmu(str(copy)) == []
    r = fmpy.simulate_fmu(str(copy), stop_time=1e-3, output_interval=H)
    assert r["edge_pressure"].shape == (11, 11)
    assert np.allclose(r["edge_x"][0], np.linspace(0, 0.1, 11))
    sums = r["edge_pressure"] @ edge_shares(r["edge_x"][0])
    assert np.abs(sums - r["normal_force"]).max() <= 1e-12 * r["normal_force"].max()
    # Setting nx alone through fmpy's start values: the FMU's arrays grow, fmpy's stay at 21.
    with pytest.raises(FMICallException):
        fmpy.simulate_fmu(str(FMU3), stop_time=1e-3, output_interval=H, start_values={"nx": 10})


def test_simulate_fmi3_runs_another_mesh_in_one_call():
    """contactbody.fmu.simulate_fmi3 hides the configured copy: nx = 10 and ny = 8 through
    start values record 11-node arrays, the same bits as the configured copy run by hand."""
    from contactbody.fmu import simulate_fmi3
    start = {"nx": 10, "ny": 8, "friction_coefficient": 0.2}
    r = simulate_fmi3(FMU3, start_values=start, stop_time=1e-3, output_interval=H)
    assert r["edge_pressure"].shape == (11, 11) and r["normal_force"][-1] > 0
    sums = r["edge_pressure"] @ edge_shares(r["edge_x"][0])
    assert np.abs(sums - r["normal_force"]).max() <= 1e-12 * r["normal_force"].max()
    reference = fmpy.simulate_fmu(str(FMU3), stop_time=1e-3, output_interval=H,
                                  start_values={"ny": 8, "friction_coefficient": 0.2,
                                                "nx": 20})  # another mesh: must differ
    assert not np.array_equal(r["normal_force"], reference["normal_force"])


@pytest.mark.parametrize("debug_logging", [False, True])
def test_fmpy_receives_messages_only_while_logging_is_on(debug_logging):
    """FMI 3.0.2, 2.3.1: while loggingOn is false the FMU does not call logMessage at all, and
    otherwise only for enabled categories, errors included ("respecting the current logging
    settings"). Through fmpy's simulate_fmu: the paper's undamped scene (F = 1.2, warned
    about at initialization), then a refused start value (an error)."""
    calls = []

    def logger(env, status, category, message):
        calls.append((status, category.decode(), message.decode()))

    fmpy.simulate_fmu(str(FMU3), stop_time=2e-4, output_interval=1e-4, logger=logger,
                      debug_logging=debug_logging, output=["energy"])
    with pytest.raises(Exception):
        fmpy.simulate_fmu(str(FMU3), stop_time=2e-4, output_interval=1e-4, logger=logger,
                          debug_logging=debug_logging, start_values={"density": -1.0})
    if not debug_logging:
        assert calls == []
        return
    warnings = [m for s, c, m in calls if s == 1]
    assert any("measured unstable region" in m for m in warnings), calls
    assert all(c == "logStatusWarning" for s, c, m in calls if s == 1)
    assert any(s == 3 and c == "logStatusError" and "density" in m for s, c, m in calls), calls


def test_only_enabled_categories_reach_the_logger(md3, unzipped3):
    """With logging on but only logEvents enabled, an FMI 3.0 instance passes its events and
    neither the initialization warning nor an error; enabling logStatusError lets errors in."""
    calls = []
    slave = FMU3Slave(guid=md3.guid, unzipDirectory=unzipped3,
                      modelIdentifier=md3.coSimulation.modelIdentifier, instanceName="cats")
    slave.instantiate(loggingOn=True,
                      logMessage=lambda e, s, c, m: calls.append((s, c.decode(), m.decode())))
    try:
        slave.setDebugLogging(False, [])
        slave.setDebugLogging(True, ["logEvents"])
        slave.enterInitializationMode(startTime=0.0)
        slave.exitInitializationMode()
        slave.doStep(0.0, 1e-4)
        assert calls and {c for s, c, m in calls} == {"logEvents"}, calls
        with pytest.raises(FMICallException):
            slave.getFloat64([999999])
        assert all(s == 0 for s, c, m in calls), calls
        slave.setDebugLogging(True, ["logStatusError"])
        with pytest.raises(FMICallException):
            slave.getFloat64([999999])
        assert calls[-1][:2] == (3, "logStatusError"), calls[-1]
    finally:
        slave.freeInstance()


@pytest.mark.parametrize("type_, ctype", [
    ("Float32", ctypes.c_float), ("Int8", ctypes.c_int8), ("UInt8", ctypes.c_uint8),
    ("Int16", ctypes.c_int16), ("UInt16", ctypes.c_uint16), ("UInt32", ctypes.c_uint32),
    ("Boolean", ctypes.c_bool), ("Float64", ctypes.c_double), ("Int32", ctypes.c_int32),
    ("Int64", ctypes.c_int64), ("UInt64", ctypes.c_uint64)])
def test_values_without_value_references_are_refused_alike(make3, type_, ctype):
    """No value references hold no values: nValues = 5 is an error for every type, those the
    FMU has variables of and those it has none of (issue 42, F); nValues = 0 is fine."""
    inst = make3()
    inst.enterInitializationMode()
    values = (ctype * 5)()
    references = (ctypes.c_uint32 * 1)()
    for function in (f"fmi3Get{type_}", f"fmi3Set{type_}"):
        call = getattr(inst.slave, function)  # fmpy's wrapper: raises on a status other than OK
        with pytest.raises(FMICallException):
            call(inst.slave.component, references, 0, values, 5)
        assert "nValues is 5, the variables hold 0" in inst.text(), inst.text()[-300:]
        call(inst.slave.component, references, 0, values, 0)


@pytest.mark.parametrize("standard", ["fmi2", "fmi3"])
def test_a_refused_call_changes_nothing_in_either_standard(model_description, unzipped, make3,
                                                           standard):
    """The decision (issue 42, E; docs/contract.md, "Refused calls"): a call refused for its
    arguments returns Error and leaves the instance as it was, in both standards alike. A run
    with refused steps in it (step size 0, -1 and NaN, a communication point other than the
    current time) continues to the same bits as a run without them."""
    from contactbody.fmu import Instance
    h = 1e-4
    names = ["energy", "normal_force", "friction_force", "top_position"]

    def run(refuse):
        if standard == "fmi2":
            inst = Instance(model_description, unzipped, "refused")
            refs = [v.valueReference for v in model_description.modelVariables if v.name in names]
            inst.setupExperiment(startTime=0)
            inst.enterInitializationMode()
            inst.exitInitializationMode()
            step = lambda t, dt: inst.doStep(t, dt)
            read = lambda: inst.getReal(refs)
        else:
            inst = make3()
            md3 = fmpy.read_model_description(str(FMU3))
            refs = [v.valueReference for v in md3.modelVariables if v.name in names]
            inst.enterInitializationMode(startTime=0)
            inst.exitInitializationMode()
            step = lambda t, dt: inst.doStep(t, dt)
            read = lambda: inst.getFloat64(refs)
        rows = []
        try:
            for k in range(6):
                if refuse and k in (2, 4):
                    for t, dt in ((k * h, 0.0), (k * h, -1.0), (k * h, float("nan")), (k * h + 0.5, h)):
                        with pytest.raises(FMICallException):
                            step(t, dt)
                step(k * h, h)
                rows.append(read())
        finally:
            if standard == "fmi2":
                inst.close()
        return rows

    assert run(refuse=True) == run(refuse=False)
