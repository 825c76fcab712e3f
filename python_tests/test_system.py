"""The body in system models: the companion FMUs, the SSP and the container FMU
against contactbody.master, coupling convergence, the power bond, the adaptive master and
the press that explicit coupling cannot hold."""
import numpy as np
import pytest
from fmpy.validation import validate_fmu

from conftest import SANITIZED
from contactbody import system as S
from contactbody.fmu import Model, SimulationFailed
from contactbody.master import Master, RollbackError

pytestmark = pytest.mark.skipif(SANITIZED, reason="runs the uninstrumented build's FMUs")


@pytest.fixture(scope="module")
def belt():
    with Master(S.belt_system()) as m:
        yield m


@pytest.fixture(scope="module")
def reference(belt):
    return belt.run_fixed(0.01, 3.125e-6)


def sup_error(r, ref, name="belt.belt_velocity"):
    return np.abs(r[name] - np.interp(r["time"], ref["time"], ref[name])).max()


@pytest.mark.parametrize("name", ["BeltDrive", "Press"])
def test_companion_fmus_are_valid_and_restore_bit_for_bit(name):
    assert validate_fmu(str(S.fmu(name))) == []
    with Model(S.fmu(name)) as a, Model(S.fmu(name)) as b:
        inputs = [v.name for v in a.description.modelVariables if v.causality == "input"]
        outputs = [v.valueReference for v in a.description.modelVariables
                   if v.causality == "output"]
        a.start({})
        for k in range(20):
            a.instance.setReal([a.variable(inputs[-1]).valueReference], [1e3 * np.sin(k)])
            a.instance.doStep(k * 1e-4, 1e-4)
        state = a.instance.getFMUstate()
        blob = a.instance.serializeFMUstate(state)

        def go(m):
            rows = []
            for k in range(20, 40):
                m.instance.setReal([m.variable(inputs[-1]).valueReference], [1e3 * np.sin(k)])
                m.instance.doStep(k * 1e-4, 1e-4)
                rows.append(m.instance.getReal(outputs))
            return rows
        expected = go(a)
        a.instance.setFMUstate(state)
        assert go(a) == expected  # rolled back in the same instance
        b.start({})
        b.instance.setFMUstate(b.instance.deSerializeFMUstate(blob))
        assert go(b) == expected  # restored into another instance


def test_ssp_container_and_master_agree_bit_for_bit(tmp_path, belt):
    """Same fixed step (1e-4 s, Jacobi): the three runs give the same belt velocity and body
    outputs to the last bit. simulate_ssp starts the inputs at 0, the container FMU at the
    sources' outputs at t0 (the static start's friction is a round-off -2e-12 N/m there): the
    master is run both ways."""
    import fmpy
    system = S.belt_system()
    ssp = S.simulate_ssp(S.write_ssp(system, tmp_path / "belt.ssp"), 0.003, 1e-4)
    container = fmpy.simulate_fmu(str(S.write_container(system, tmp_path / "c.fmu", 1e-4)),
                                  stop_time=0.003, output_interval=1e-4)
    zero_start = belt.run_fixed(0.003, 1e-4, zero_inputs=True)
    master = belt.run_fixed(0.003, 1e-4)
    n = len(master) - 1
    for name in ("belt.belt_velocity", "body.friction_force", "body.energy"):
        assert np.array_equal(ssp[name][:n], zero_start[name][1:])  # fmpy labels the step start
        assert np.array_equal(container[name.replace(".", "_")], master[name])
    assert master["belt.belt_velocity"][-1] > 0.01


def test_the_body_in_the_system_steps_as_the_standalone_fmu(belt):
    """Within a coupled run, each body step is bit-identical to the standalone FMU fed the
    same inputs: replay the foundation velocities the body received."""
    r = belt.run_fixed(0.004, 1e-4)
    received = r["belt.belt_velocity"][:-1]  # held: the belt's output at each step's start
    system = S.belt_system()
    with Model(S.fmu("ContactBody")) as body:
        body.start(system.component_parameters("body"))
        vr = body.variable("foundation_velocity").valueReference
        outputs = [body.variable(n).valueReference for n in ("friction_force", "energy",
                                                             "foundation_work")]
        for k in range(len(r) - 1):
            body.instance.setReal([vr], [received[k]])
            body.instance.doStep(k * 1e-4, 1e-4)
            assert body.instance.getReal(outputs) == [r["body.friction_force"][k + 1],
                                                      r["body.energy"][k + 1],
                                                      r["body.foundation_work"][k + 1]]


def test_the_belt_drive_runs_the_reduced_body(belt):
    """`modes` is a body parameter like any other in the system models. With every finite mode
    (209 at nx = ny = 10, redistributed_normal) the coupled run, static start included, is the
    full body's to 1e-10; with 20 modes the belt velocity and the friction force stay within 1 %
    of their largest values (measured 0.41 % and 0.63 %)."""
    full = belt.run_fixed(0.004, 1e-4)
    names = ("belt.belt_velocity", "body.friction_force", "body.energy")
    for modes, bound in ((209, 1e-10), (20, 1e-2)):
        with Master(S.belt_system(modes=modes)) as m:
            reduced = m.run_fixed(0.004, 1e-4)
        for name in names[:2] if modes == 20 else names:
            error = np.abs(reduced[name] - full[name]).max() / np.abs(full[name]).max()
            assert error <= bound, (modes, name, error)


def test_coupling_converges_at_first_order_and_the_bond_closes(belt, reference):
    """Held inputs (Jacobi): as h halves (1e-4, 5e-5, 2.5e-5 s) the sup difference of the
    belt velocity to the fine reference falls at order >= 0.9 (measured 1.38, 1.24), and
    the energy the belt gives (load_work) and the body receives (foundation_work x width)
    differ by a mismatch that halves with h (order 1.00)."""
    errors, mismatch = [], []
    for h in (1e-4, 5e-5, 2.5e-5):
        r = belt.run_fixed(0.01, h)
        errors.append(sup_error(r, reference))
        mismatch.append(abs(r["belt.load_work"][-1] - S.WIDTH * r["body.foundation_work"][-1]))
    orders = np.log2(np.array(errors[:-1]) / errors[1:])
    assert np.all(orders >= 0.9), orders
    bond_orders = np.log2(np.array(mismatch[:-1]) / mismatch[1:])
    assert np.all(np.abs(bond_orders - 1) <= 0.05), bond_orders
    assert mismatch[-1] < 5e-3 * abs(r["belt.load_work"][-1])  # measured 0.33 % at 2.5e-5 s


def test_adaptive_master_reaches_the_error_in_fewer_steps(belt, reference):
    """Against held fixed steps: the adaptive master (input-extrapolation error, tol 3e-3)
    is more accurate than h = 1.25e-5 s (1600 doSteps) with fewer doSteps than the fixed
    step that beats it, h = 6.25e-6 s (3200 doSteps). Measured: 1.75e-4 m/s in 1706."""
    adaptive = belt.run_adaptive(0.01, rtol=3e-3, atol=3e-3, h0=1e-5, h_min=3.125e-6,
                                 h_max=1e-3, extrapolate=False, estimator="input")
    adaptive_error, adaptive_steps = sup_error(adaptive, reference), belt.do_steps
    fine = belt.run_fixed(0.01, 1.25e-5)
    assert adaptive_error < sup_error(fine, reference)
    assert adaptive_steps < 2 * belt.do_steps


def test_a_rollback_that_is_not_bit_identical_is_refused(belt):
    belt.initialize()
    belt.step(1e-4)
    snapshot = belt.save()
    belt.step(1e-4)
    after = dict(belt.values)
    belt.restore(snapshot)
    belt.step(1e-4)
    assert belt.values == after  # replay after rollback: the same bits
    states, (t, values, held, previous) = snapshot
    corrupted = (states, (t, {**values, "belt.belt_velocity": values["belt.belt_velocity"]
                              + 1e-16}, held, previous))
    with pytest.raises(RollbackError):
        belt.restore(corrupted)
    belt.free(snapshot)


def test_the_press_blows_up_explicitly_and_holds_strongly_coupled():
    """The press on the body: explicit (Jacobi) coupling at h = 1e-4 s diverges: the body's
    step fails with fmi2Error once the press drives the top below the foundation (before the
    guard, the energy went on to 7.7e18 J/m under fmi2OK). Iterated to convergence at each step (Aitken; the
    body's reaction, a step average, held at its guess) it is stable over 30 ms: the energy
    of the last third stays below that of the first, the press settles where the body
    carries the actuator's 150 N (within 2 %), and h = 1e-4 and 5e-5 s agree to 0.1 %."""
    with Master(S.press_system()) as m:
        with pytest.raises(SimulationFailed) as failure:
            m.run_fixed(0.01, 1e-4)
        assert "at or below the foundation" in str(failure.value)
        ends = []
        for h in (1e-4, 5e-5):
            r = m.run_fixed(0.03, h, iterate=True)
            third = len(r) // 3
            assert r["body.energy"][2 * third:].max() <= r["body.energy"][:third].max()
            late = r["time"] > 0.025
            assert np.mean(r["press.reaction_force"][late]) == pytest.approx(150, rel=0.02)
            ends.append(r["press.position"][-1])
        assert ends[0] == pytest.approx(ends[1], rel=1e-3)


def test_the_container_runs_alone_in_plain_fmpy(tmp_path, belt):
    """Plain fmpy.simulate_fmu(container), with no argument but the file, in
    a process that has only fmpy (no contactbody), runs the documented scene (its
    DefaultExperiment: 10 ms at 1e-4 s) bit for bit as the master does."""
    import subprocess
    import sys
    path = S.write_container(S.belt_system(), tmp_path / "c.fmu", 1e-4, stop_time=0.01)
    code = ("import sys, numpy as np, fmpy; r = fmpy.simulate_fmu(sys.argv[1]); "
            "np.save(sys.argv[2], np.stack([r['time'], r['belt_belt_velocity'], "
            "r['body_energy']]))")
    subprocess.run([sys.executable, "-c", code, str(path), str(tmp_path / "plain.npy")],
                   check=True, capture_output=True, cwd=tmp_path)
    plain = np.load(tmp_path / "plain.npy")
    master = belt.run_fixed(0.01, 1e-4)
    assert plain.shape[1] == len(master) and plain[0, -1] == pytest.approx(0.01)
    assert np.array_equal(plain[1], master["belt.belt_velocity"])
    assert np.array_equal(plain[2], master["body.energy"])


def test_ssp_connectors_carry_the_variables_types(tmp_path):
    import zipfile
    system = S.belt_system()
    system.record = list(system.record) + ["body.active_contact_nodes"]
    with zipfile.ZipFile(S.write_ssp(system, tmp_path / "b.ssp", stop_time=0.03)) as z:
        ssd = z.read("SystemStructure.ssd").decode()
    assert ('<ssd:Connector name="active_contact_nodes" kind="output"><ssc:Integer/>' in ssd)
    assert '<ssd:Connector name="friction_force" kind="output"><ssc:Real/>' in ssd
    assert 'stopTime="0.03"' in ssd


@pytest.mark.parametrize("name", ["belt", "press"])
def test_both_ssps_run_alone_in_plain_fmpy(tmp_path, name):
    """fmpy 0.3.32's simulate_ssp applies no parameter binding of the .ssd
    (only its parameter_set argument), so each component in the archive is a configured copy
    that carries the system's values as its own start values. Plain simulate_ssp, in a process
    with only fmpy, then equals the project's run (with the .ssv) bit for bit; before, the body
    ran with its defaults (E(0) = 0.1875 instead of the system's)."""
    import subprocess
    import sys
    system = getattr(S, f"{name}_system")()
    ssp = S.write_ssp(system, tmp_path / f"{name}.ssp", stop_time=0.003)
    code = ("import sys, numpy as np; from fmpy.ssp.simulation import simulate_ssp; "
            "assert 'contactbody' not in sys.modules; "
            "r = simulate_ssp(sys.argv[1], stop_time=0.003, step_size=1e-4); "
            "np.save(sys.argv[2], np.stack([r[n] for n in r.dtype.names]))")
    subprocess.run([sys.executable, "-c", code, str(ssp), str(tmp_path / "plain.npy")],
                   check=True, capture_output=True, cwd=tmp_path)
    plain = np.load(tmp_path / "plain.npy")
    ours = S.simulate_ssp(ssp, 0.003, 1e-4)
    for k, column in enumerate(ours.dtype.names):
        assert np.array_equal(plain[k], ours[column]), column
    with Master(system) as m:
        master = m.run_fixed(0.003, 1e-4, zero_inputs=True)
    n = len(master) - 1
    assert np.array_equal(plain[ours.dtype.names.index("body.energy")][:n],
                          master["body.energy"][1:])


def test_a_configured_copy_is_valid_and_keeps_its_values_across_reset(tmp_path):
    """The copy's start values are its own at instantiation and after fmi2Reset; fmpy
    validates it; a malformed start_values.txt fails fmi2Instantiate with the line."""
    import zipfile
    path = tmp_path / "Body.fmu"
    path.write_bytes(S.configured_copy(S.fmu("ContactBody"), {"friction_coefficient": 0.37,
                                                              "nx": 8, "ny": 8}))
    assert validate_fmu(str(path)) == []
    with Model(path) as model:
        for _ in range(2):  # the second run starts from fmi2Reset
            rows, _ = model.run({}, 1e-4, 1e-4, ["energy"])
            assert model.instance.getReal([model.variables["friction_coefficient"].valueReference]) == [0.37]
    broken = tmp_path / "Broken.fmu"
    with zipfile.ZipFile(path) as src, zipfile.ZipFile(broken, "w") as dst:
        for info in src.infolist():
            dst.writestr(info, b"friction_coefficient 0.3\n" if info.filename ==
                         "resources/start_values.txt" else src.read(info))
    import fmpy
    from contactbody import fmu as F
    unzipped = tmp_path / "broken"
    fmpy.extract(str(broken), str(unzipped))
    before = set(F._messages_by_instance)
    with pytest.raises(Exception, match="instantiate"):
        F.Instance(fmpy.read_model_description(str(broken)), unzipped, "broken")
    said = [m[2] for k, v in F._messages_by_instance.items() if k not in before for m in v]
    assert any("start_values.txt, line 1: expected 'name = value'" in m for m in said), said


def test_system_models_take_the_fmus_beside_contactbody_fmu(tmp_path, monkeypatch):
    """The package finds its FMUs outside a checkout's build/ too: the system models use the
    companions beside $CONTACTBODY_FMU."""
    import shutil
    from conftest import FMU
    for name in ("ContactBody", "BeltDrive", "Press"):
        shutil.copy(FMU.with_name(f"{name}.fmu"), tmp_path)
    monkeypatch.setenv("CONTACTBODY_FMU", str(tmp_path / "ContactBody.fmu"))
    for system in (S.belt_system(), S.press_system()):
        assert {p.parent for p in system.components.values()} == {tmp_path.resolve()}
