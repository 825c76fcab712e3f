"""Field output: .vtu snapshots and a .pvd collection, readable by meshio, carrying
the same state as a run without field output; an unwritable directory fails initialization."""
import pathlib

import numpy as np
import pytest
from fmpy import simulate_fmu

from conftest import Instance

from contactbody import fields

SCENE = dict(nx=8, ny=8, mass_matrix=0, internal_step=1e-5)  # consistent M: energies in numpy


def run(fmu_path, **extra):
    return simulate_fmu(fmu_path, stop_time=2e-3, output_interval=1e-4,
                        start_values={**SCENE, **extra})


def test_vtu_files_load_with_meshio_and_carry_the_state_of_a_plain_run(fmu_path, tmp_path):
    plain = run(fmu_path)
    with_fields = run(fmu_path, result_directory=str(tmp_path), field_output_interval=2e-4)
    # Writing fields changes nothing in the outputs.
    for name in ("energy", "friction_work", "normal_force", "top_reaction_y"):
        np.testing.assert_array_equal(plain[name], with_fields[name])

    snapshots = fields.read_collection(tmp_path / "contactbody.pvd")
    times = [t for t, _ in snapshots]
    np.testing.assert_allclose(times, np.arange(11) * 2e-4, atol=1e-12)
    for t, path in snapshots:
        points, triangles, data = fields.read_field(path)
        assert points.shape == (81, 2) and triangles.shape == (128, 3)
        u, v = data["displacement"], data["velocity"]
        # The energies of the plain run at the same time, recomputed from the fields alone.
        k = int(np.argmin(np.abs(plain["time"] - t)))
        kinetic = fields.kinetic_energy(points, triangles, v, 1000)
        strain = fields.strain_energy(points, triangles, u, 300e6, 150e6)
        assert kinetic == pytest.approx(plain["kinetic_energy"][k], rel=1e-9, abs=1e-15)
        assert strain == pytest.approx(plain["strain_energy"][k], rel=1e-9)
        # Contact forces live on the bottom edge only, pressing the body up.
        force = data["contact_force"]
        bottom = points[:, 1] == 0
        assert np.all(force[~bottom] == 0) and np.all(force[bottom, 1] >= 0)


def test_initial_energy_from_the_first_snapshot(fmu_path, tmp_path):
    run(fmu_path, result_directory=str(tmp_path))
    (t0, first), *_ = fields.read_collection(tmp_path / "contactbody.pvd")
    points, triangles, data = fields.read_field(first)
    assert t0 == 0
    assert fields.strain_energy(points, triangles, data["displacement"], 300e6, 150e6) == \
        pytest.approx(0.1875, rel=1e-12)


def test_unwritable_directory_is_an_error_at_initialization(model_description, unzipped, vr,
                                                            tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    inst = Instance(model_description, unzipped)
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setString([vr["result_directory"]], [str(blocker / "out")])
        with pytest.raises(Exception):
            inst.exitInitializationMode()
        assert "result_directory" in inst.text() and "fmi2ExitInitializationMode" in inst.text()
    finally:
        inst.close()


def test_string_parameter_checks(model_description, unzipped, vr, tmp_path):
    inst = Instance(model_description, unzipped)
    try:
        inst.setString([vr["result_directory"]], [str(tmp_path)])
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        assert inst.getString([vr["result_directory"]]) == [str(tmp_path).encode()]
        with pytest.raises(Exception):
            inst.setString([vr["result_directory"]], ["x" * 5000])
        with pytest.raises(Exception):
            inst.setString([vr["result_directory"]], ["bad\nname"])
        with pytest.raises(Exception):
            inst.setString([vr["nx"]], ["20"])  # not a String variable
        assert inst.getString([vr["result_directory"]]) == [str(tmp_path).encode()]
        inst.exitInitializationMode()
        with pytest.raises(Exception):  # fixed after initialization
            inst.setString([vr["result_directory"]], [str(tmp_path / "other")])
        assert "fixed" in inst.text()
    finally:
        inst.close()


def test_rollback_rewrites_the_collection(model_description, unzipped, vr, tmp_path):
    inst = Instance(model_description, unzipped)
    try:
        for name, value in SCENE.items():
            inst.setInteger([vr[name]], [value]) if isinstance(value, int) else \
                inst.setReal([vr[name]], [value])
        inst.setString([vr["result_directory"]], [str(tmp_path)])
        inst.setReal([vr["field_output_interval"]], [1e-4])
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.exitInitializationMode()
        t = 0.0
        for _ in range(3):
            inst.doStep(t, 1e-4)
            t += 1e-4
        saved = inst.getFMUstate()
        energy_saved = inst.getReal([vr["energy"]])
        for _ in range(4):
            inst.doStep(t, 1e-4)
            t += 1e-4
        assert len(fields.read_collection(tmp_path / "contactbody.pvd")) == 8
        inst.setFMUstate(saved)
        assert len(fields.read_collection(tmp_path / "contactbody.pvd")) == 4
        assert len(list(tmp_path.glob("*.vtu"))) == 4  # the rolled-back snapshots' files too
        assert inst.getReal([vr["energy"]]) == energy_saved
        inst.doStep(3e-4, 1e-4)
        listed = fields.read_collection(tmp_path / "contactbody.pvd")
        assert [round(t / 1e-4) for t, _ in listed] == [0, 1, 2, 3, 4]
        inst.freeFMUstate(saved)
    finally:
        inst.close()


def test_a_rerun_leaves_only_the_files_its_collection_lists(fmu_path, tmp_path):
    """A longer run, then a shorter one into the same result_directory: the directory holds
    exactly the .vtu files the new .pvd lists (other files are left alone)."""
    (tmp_path / "notes.txt").write_text("mine")
    run(fmu_path, result_directory=str(tmp_path), field_output_interval=1e-4)
    assert len(list(tmp_path.glob("*.vtu"))) == 21
    simulate_fmu(fmu_path, stop_time=5e-4, output_interval=1e-4,
                 start_values={**SCENE, "result_directory": str(tmp_path),
                               "field_output_interval": 1e-4})
    listed = fields.read_collection(tmp_path / "contactbody.pvd")
    assert sorted(p.name for p in tmp_path.glob("*.vtu")) == sorted(
        pathlib.Path(f).name for _, f in listed)
    assert len(listed) == 6 and (tmp_path / "notes.txt").read_text() == "mine"


def test_nested_interpolation_is_exact_for_p1_fields():
    # A coarse P1 field, evaluated on the 2x refined mesh, has the same L2 norm there.
    def grid(n):
        i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1))
        pts = np.stack([i.ravel(), j.ravel()], axis=1) * (0.1 / n)
        tris = []
        for jj in range(n):
            for ii in range(n):
                a, b, c, d = (jj * (n + 1) + ii, jj * (n + 1) + ii + 1,
                              (jj + 1) * (n + 1) + ii, (jj + 1) * (n + 1) + ii + 1)
                tris += [[a, b, d], [a, d, c]] if (ii + jj) % 2 == 0 else [[a, b, c], [b, d, c]]
        return pts, np.array(tris)
    rng = np.random.default_rng(1)
    cp, ct = grid(4)
    fp, ft = grid(8)
    values = rng.normal(size=(len(cp), 2))
    fine = fields.interpolate_nested(cp, values, 4, 4, 0.1, 0.1, fp)
    assert fields.l2_squared(fp, ft, fine) == pytest.approx(fields.l2_squared(cp, ct, values), rel=1e-12)
    assert fields.h1_squared(fp, ft, fine) == pytest.approx(fields.h1_squared(cp, ct, values), rel=1e-12)


def test_edge_history_adds_up_to_the_scalar_outputs(fmu_path, tmp_path):
    """contactbody_edge.npy (edge_output_interval): one record per output time; the node
    pressures and friction densities times their share of the edge sum to normal_force and
    friction_force (the same step averages) to round-off, and the node states count the
    active and slipping nodes of the last substep."""
    r = simulate_fmu(fmu_path, stop_time=2e-3, output_interval=1e-4,
                     start_values={**SCENE, "friction_coefficient": 0.3,
                                   "result_directory": str(tmp_path),
                                   "edge_output_interval": 1e-4},
                     output=["normal_force", "friction_force", "active_contact_nodes",
                             "slipping_contact_nodes", "max_penetration"])
    e = np.load(tmp_path / "contactbody_edge.npy")
    assert len(e) == len(r) and np.array_equal(e["time"], r["time"])
    hx = 0.1 / SCENE["nx"]
    share = np.full(SCENE["nx"] + 1, hx)
    share[[0, -1]] = hx / 2
    np.testing.assert_allclose(e["pressure"] @ share, r["normal_force"], rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(e["friction"] @ share, r["friction_force"], rtol=1e-12, atol=1e-6)
    assert np.array_equal((e["state"][1:] > 0).sum(1), r["active_contact_nodes"][1:])
    assert np.array_equal((e["state"][1:] == 2).sum(1), r["slipping_contact_nodes"][1:])
    assert np.allclose(e["x"][0], np.arange(SCENE["nx"] + 1) * hx)
    # the end-of-step gaps are the last substep's ends: max_penetration covers them
    assert np.all(r["max_penetration"][1:] >= (-e["gap"][1:]).max(1) - 1e-15)


def test_edge_history_follows_a_rollback(model_description, unzipped, vr, tmp_path):
    inst = Instance(model_description, unzipped)
    try:
        inst.setString([vr["result_directory"]], [str(tmp_path)])
        inst.setReal([vr["edge_output_interval"]], [1e-4])
        inst.setInteger([vr["nx"], vr["ny"]], [8, 8])
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.exitInitializationMode()
        for k in range(3):
            inst.doStep(k * 1e-4, 1e-4)
        saved = inst.getFMUstate()
        for k in range(3, 7):
            inst.doStep(k * 1e-4, 1e-4)
        assert len(np.load(tmp_path / "contactbody_edge.npy")) == 8
        inst.setFMUstate(saved)
        assert len(np.load(tmp_path / "contactbody_edge.npy")) == 4
        inst.doStep(3e-4, 1e-4)
        times = np.load(tmp_path / "contactbody_edge.npy")["time"]
        assert np.allclose(times, np.arange(5) * 1e-4)
        inst.freeFMUstate(saved)
    finally:
        inst.close()


def test_edge_history_needs_a_result_directory(instance, vr):
    instance.setReal([vr["edge_output_interval"]], [1e-4])
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    with pytest.raises(Exception):
        instance.exitInitializationMode()
    assert "needs a result_directory" in instance.text()
