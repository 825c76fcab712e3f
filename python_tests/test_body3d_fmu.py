"""ContactBody3D.fmu and ContactBody3D_fmi3.fmu: the 3D model, from the same variable table as
ContactBody (fmu_src/variables.cpp), driven through fmpy. Its units are a solid body's (N, J),
its foundation slides in x and z, and everything that exists for the 2D model runs on it: the
five variants with the energy balance, the static start, force control, the initial gap, state
save and restore, reset, refused calls, field output and the edge history."""
import base64
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import zipfile

import fmpy
from fmpy.fmi1 import FMICallException
import numpy as np
import pytest

from conftest import FMU, ROOT, SANITIZED, Instance, fastest_kernels_of_this_cpu

FMU3D = FMU.with_name("ContactBody3D.fmu")
FMU3D_FMI3 = FMU.with_name("ContactBody3D_fmi3.fmu")
DATA = pathlib.Path(__file__).parent / "data"
# Short runs: the default block (343 nodes, 49 contact nodes) at the default 4e-6 s substeps.
STOP, H = 1e-3, 1e-4
WORK_TERMS = ["clamp_work", "normal_contact_work", "friction_work", "damping_work", "energy",
              "friction_dissipation", "foundation_work"]


@pytest.fixture(scope="module")
def unzipped3d():
    directory = tempfile.mkdtemp(prefix="ContactBody3D_")
    fmpy.extract(str(FMU3D), directory)
    return directory


@pytest.fixture(scope="module")
def md3d():
    return fmpy.read_model_description(str(FMU3D))


def simulate(stop=STOP, output=None, **start):
    return fmpy.simulate_fmu(str(FMU3D), stop_time=stop, output_interval=H,
                             start_values=start, output=output)


def balance_residual(r):
    """max |E - E(0) - (clamp + normal contact + friction - damping)| over max(E(0), |works|)."""
    lhs = r["energy"] - r["energy"][0]
    rhs = r["clamp_work"] + r["normal_contact_work"] + r["friction_work"] - r["damping_work"]
    scale = max(r["energy"][0], *(np.abs(r[w]).max() for w in WORK_TERMS))
    return np.abs(lhs - rhs).max() / scale


# ---- the modelDescription: one table, the 3D model's rows and units ----

@pytest.mark.parametrize("fmu, committed", [
    (FMU3D, "modelDescription3D.xml"), (FMU3D_FMI3, "modelDescription3D_fmi3.xml")])
def test_committed_model_description_is_the_builds(fmu, committed):
    with zipfile.ZipFile(fmu) as z:
        generated = z.read("modelDescription.xml").decode()
    assert generated == (ROOT / "modelDescription" / committed).read_text(), (
        f"modelDescription/{committed} is stale: copy it from build/fmu/{fmu.stem}/")


def test_units_are_a_solid_bodys_and_the_2d_models_stay_per_metre(md3d):
    solid = {v.name: v for v in md3d.modelVariables}
    planar = {v.name: v for v in fmpy.read_model_description(str(FMU)).modelVariables}
    for name in ["normal_force", "friction_force", "top_reaction_x", "top_reaction_y", "top_force"]:
        assert (solid[name].unit, planar[name].unit) == ("N", "N/m"), name
    for name in ["energy", "friction_work", "clamp_work", "max_energy"]:
        assert (solid[name].unit, planar[name].unit) == ("J", "J/m"), name
    assert (solid["top_mass"].unit, planar["top_mass"].unit) == ("kg", "kg/m")
    assert not [v.name for v in md3d.modelVariables if v.unit and v.unit.endswith("/m") and
                v.unit not in ("s/m",)]  # no per-metre label on a 3D quantity
    z_names = {"foundation_velocity_z", "initial_velocity_z", "friction_force_z", "top_reaction_z"}
    assert z_names <= set(solid) and not z_names & set(planar)
    assert solid["foundation_velocity_z"].causality == "input"
    assert not {"width", "height", "nx", "ny"} & set(solid)
    assert solid["mesh"].start == "block.msh"
    assert md3d.coSimulation.modelIdentifier == "ContactBody3D"
    with zipfile.ZipFile(FMU3D) as z:
        assert "resources/block.msh" in z.namelist()


def test_fmi3_edge_arrays_hold_x_z_pressure_friction_slip_gap_state():
    md = fmpy.read_model_description(str(FMU3D_FMI3))
    arrays = {v.name for v in md.modelVariables if v.dimensions}
    assert arrays == {"edge_x", "edge_z", "edge_pressure", "edge_friction", "edge_friction_z",
                      "edge_slip_velocity", "edge_slip_velocity_z", "edge_gap", "edge_state"}
    edge_nodes = next(v for v in md.modelVariables if v.name == "edge_nodes")
    assert int(edge_nodes.start) == 49  # the default block's 7 x 7 contact nodes


# ---- physics through the FMU ----

# Under the sanitizer (an instrumented run of the same code, 5x slower) the variants' code paths
# run once each in variants 0, 1 and 4: CI's time (docs/testing_and_benchmarks.md).
SANITIZED_VARIANTS = [0, 1, 4] if SANITIZED else range(5)


@pytest.mark.parametrize("law", ["coulomb", "slip_rate"])
@pytest.mark.parametrize("variant", SANITIZED_VARIANTS)
def test_energy_balance_closes_in_every_variant_sliding_in_x_and_z(variant, law):
    """Sliding at (12, 16) m/s with F = 0.5, damped (so that static friction and damping both
    work), static_friction_ratio 1.5, with Coulomb's law and with the slip-rate law (a Stribeck
    drop over 5 m/s and a viscous term): the balance closes to 1e-9 of max(E(0), |works|)."""
    rate = {"stribeck_velocity": 5.0, "viscous_friction": 0.01} if law == "slip_rate" else {}
    r = simulate(mass_matrix=variant, friction_coefficient=0.5, static_friction_ratio=1.5,
                 foundation_velocity=12.0, foundation_velocity_z=16.0, damping_stiffness=2e-6,
                 output=WORK_TERMS + ["friction_force", "friction_force_z", "normal_force"], **rate)
    assert r["normal_force"][-1] > 0 and r["friction_dissipation"][-1] > 0
    assert balance_residual(r) < 1e-9


def test_friction_is_isotropic_opposite_the_slip_and_within_the_cone():
    """The foundation at 20 m/s along 0.6 rad in the x-z plane drags every slipping node along
    its motion: the total friction force points along the foundation's velocity to 1e-3 rad
    (the nodes' own velocities are small beside 20 m/s), and at every contact node of the FMI
    3.0 arrays |friction| <= F pressure (step averages of vectors)."""
    angle, speed, F = 0.6, 20.0, 0.4
    names = ["friction_force", "friction_force_z", "normal_force", "edge_pressure",
             "edge_friction", "edge_friction_z", "edge_slip_velocity", "edge_slip_velocity_z",
             "edge_state"]
    r = fmpy.simulate_fmu(str(FMU3D_FMI3), stop_time=STOP, output_interval=H, output=names,
                          start_values={"friction_coefficient": F,
                                        "foundation_velocity": speed * np.cos(angle),
                                        "foundation_velocity_z": speed * np.sin(angle),
                                        "damping_stiffness": 2e-6})
    fx, fz = r["friction_force"][-1], r["friction_force_z"][-1]
    assert abs(np.arctan2(fz, fx) - angle) < 1e-3
    assert np.hypot(fx, fz) == pytest.approx(F * r["normal_force"][-1], rel=1e-3)
    for row in r:
        magnitude = np.hypot(row["edge_friction"], row["edge_friction_z"])
        assert np.all(magnitude <= F * row["edge_pressure"] * (1 + 1e-8) + 1e-9)
    last = r[-1]
    slipping = last["edge_state"] == 2
    assert slipping.sum() > 0
    slip_angle = np.arctan2(-last["edge_slip_velocity_z"], -last["edge_slip_velocity"])[slipping]
    assert np.all(np.abs(slip_angle - angle) < 1e-2)


def test_a_foundation_turning_from_x_to_z_turns_the_friction_with_it():
    """foundation_velocity ramps from 20 to 0 and foundation_velocity_z from 0 to 20 (input
    derivatives through input_interpolation = ramp): the friction force turns from x to z. What
    stays across the new direction 0.2 ms after the turn (measured 1.1 %) is the body's own x
    motion relaxing, which the slip velocity carries."""
    md = fmpy.read_model_description(str(FMU3D))
    from fmpy.simulation import Input  # noqa: F401  (fmpy takes the structured array)
    times = np.array([0.0, 2e-4, 8e-4, 1e-3])
    signals = np.array(list(zip(times, [20, 20, 0, 0], [0, 0, 20, 20])),
                       dtype=[("time", float), ("foundation_velocity", float),
                              ("foundation_velocity_z", float)])
    r = fmpy.simulate_fmu(str(FMU3D), stop_time=1e-3, output_interval=5e-5, input=signals,
                          start_values={"friction_coefficient": 0.3, "damping_stiffness": 2e-6,
                                        "input_interpolation": 1},
                          output=["friction_force", "friction_force_z", "normal_force"])
    assert md.coSimulation.canInterpolateInputs
    early, late = r[r["time"] <= 2e-4][-1], r[-1]
    assert abs(early["friction_force_z"]) < 1e-2 * abs(early["friction_force"])
    assert abs(late["friction_force"]) < 5e-2 * abs(late["friction_force_z"])
    assert early["friction_force"] > 0 and late["friction_force_z"] > 0


@pytest.mark.parametrize("variant, law", [(v, "coulomb") for v in SANITIZED_VARIANTS] + [(1, "slip_rate"), (4, "slip_rate")])
def test_reduced_body_closes_its_balance_in_every_variant(variant, law):
    """modes = 60 (the massless edge, the default for variants 1 and 2; the tangential-mass
    edge for 0, 3, 4), sliding along (12, 16) m/s with static friction, and the slip-rate law:
    the balance closes to 1e-9 of max(E(0), |works|)."""
    rate = {"stribeck_velocity": 5.0, "viscous_friction": 0.01} if law == "slip_rate" else {}
    r = simulate(modes=60, mass_matrix=variant, friction_coefficient=0.5, static_friction_ratio=1.5,
                 foundation_velocity=12.0, foundation_velocity_z=16.0, damping_stiffness=2e-6,
                 output=WORK_TERMS + ["normal_force"], **rate)
    assert r["normal_force"][-1] > 0 and r["friction_dissipation"][-1] > 0
    assert balance_residual(r) < 1e-9


def test_the_blow_up_guard_stops_a_3d_body_naming_its_energy_in_joules(unzipped3d, md3d):
    """max_energy = 0.03 J, 1.6 E(0), for the block sliding undamped with F = 1.2 (the defaults, which
    the warning says are unstable): the step that passes it fails with fmi2Error, its message
    names the energy, and the outputs stay those of the step's start."""
    vr = {v.name: v.valueReference for v in md3d.modelVariables}
    inst = Instance(md3d, unzipped3d)
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setReal([vr["max_energy"]], [0.03])
    inst.exitInitializationMode()
    energy = inst.getReal([vr["energy"]])[0]
    assert energy < 0.02  # E(0): 0.019 J
    with pytest.raises(FMICallException):
        for k in range(200):
            inst.doStep(k * H, H)
            energy = inst.getReal([vr["energy"]])[0]
    errors = [text for status, _, text in inst.messages if status == 3]
    assert errors and "exceeds" in errors[-1] and " J" in errors[-1], errors
    assert inst.getReal([vr["energy"]])[0] == energy  # the failed step's start
    inst.close()


@pytest.mark.parametrize("edge", [1, 2])  # massless, tangential_mass
def test_reduced_body_slides_in_x_and_z_and_closes_its_balance(edge):
    """modes = 120 of the block, both edges, friction sliding along (12, 16) m/s: the balance
    closes to 1e-9, the friction has its z share, and the normal force is the full body's to
    a few per cent (120 of its 833 finite modes, 735 with the tangential edge)."""
    names = WORK_TERMS + ["friction_force", "friction_force_z", "normal_force", "top_reaction_z"]
    common = dict(friction_coefficient=0.5, foundation_velocity=12.0, foundation_velocity_z=16.0,
                  damping_stiffness=2e-6, output=names)
    reduced = simulate(modes=120, reduced_edge=edge, **common)
    full = simulate(**common)
    assert balance_residual(reduced) < 1e-9
    assert reduced["friction_force_z"][-1] == pytest.approx(16 / 12 * reduced["friction_force"][-1], rel=0.05)
    assert reduced["normal_force"][-1] == pytest.approx(full["normal_force"][-1], rel=0.05)


def test_static_start_is_at_rest_and_in_balance():
    """initial_state = static: no kinetic energy, the clamp's push equals the contact's, and a
    step without a foundation motion keeps it (the normal force moves by < 1e-6)."""
    r = simulate(initial_state=1, foundation_velocity=0.0, friction_coefficient=0.5,
                 output=["kinetic_energy", "normal_force", "top_reaction_y", "top_reaction_x",
                         "top_reaction_z", "friction_force", "friction_force_z"])
    assert r["kinetic_energy"][0] == 0
    assert r["normal_force"][0] > 0
    assert r["normal_force"][0] == pytest.approx(-r["top_reaction_y"][0], rel=1e-9)
    assert r["friction_force"][0] == pytest.approx(-r["top_reaction_x"][0], abs=1e-9 * r["normal_force"][0])
    assert r["friction_force_z"][0] == pytest.approx(-r["top_reaction_z"][0], abs=1e-9 * r["normal_force"][0])
    assert np.abs(r["normal_force"] / r["normal_force"][0] - 1).max() < 1e-6
    assert r["kinetic_energy"].max() < 1e-12 * r["normal_force"][0] * 2.5e-5


def test_force_control_settles_on_the_pressing_force():
    """top_control = force, 2000 N, the static start: the contact carries the force, and the
    plate's u_x = u_z = 0 leaves no x or z reaction without friction."""
    r = simulate(top_control=1, top_force=2000.0, initial_state=1, friction_coefficient=0.0,
                 foundation_velocity=0.0, output=["normal_force", "top_position", "top_reaction_z",
                                                  "kinetic_energy"])
    assert r["normal_force"][0] == pytest.approx(2000.0, rel=1e-8)
    assert r["normal_force"][-1] == pytest.approx(2000.0, rel=1e-6)
    assert r["top_position"][0] < 0


def test_an_initial_gap_keeps_the_body_off_the_foundation():
    r = simulate(initial_gap=1e-4, output=["normal_force", "active_contact_nodes", "max_penetration",
                                            "energy", "friction_work"])
    assert np.all(r["normal_force"] == 0) and np.all(r["active_contact_nodes"] == 0)
    assert np.all(r["max_penetration"] == 0) and np.all(r["friction_work"] == 0)


def test_initial_velocity_z_is_kinetic_energy_of_the_moving_dofs():
    """A body at rest but for initial_velocity_z = 1 m/s, off the foundation: E(0) is the
    kinetic energy of the free dofs' mass, below the block's whole ½ m v² = ½ 1 kg (1 m/s)²."""
    r = simulate(initial_gap=1e-3, initial_velocity_z=1.0, top_displacement=0.0,
                 output=["kinetic_energy", "strain_energy"])
    assert 0.4 < r["kinetic_energy"][0] < 0.5
    assert r["strain_energy"][0] == 0


# ---- the FMU around the model ----

def test_refused_settings_name_what_is_wrong(unzipped3d, md3d):
    vr = {v.name: v.valueReference for v in md3d.modelVariables}
    cases = [({"mesh": ""}, "a 3D body comes from a Gmsh file"),
             ({"modes": 1999}, "finite modes"),
             ({"initial_state": 1, "initial_velocity_z": 0.5}, "initial_velocity_y and initial_velocity_z must be 0"),
             ({"mesh": str(DATA / "outside" / "missing.msh")}, "missing.msh")]
    for values, expected in cases:
        inst = Instance(md3d, unzipped3d)
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        for name, value in values.items():
            if isinstance(value, str):
                inst.setString([vr[name]], [value])
            elif isinstance(value, int):
                inst.setInteger([vr[name]], [value])
            else:
                inst.setReal([vr[name]], [value])
        with pytest.raises(FMICallException):
            inst.exitInitializationMode()
        assert expected in inst.text(), (values, inst.text())
        inst.close()


def test_a_2d_mesh_is_refused_and_the_2d_model_refuses_tetrahedra(unzipped3d, md3d, tmp_path):
    from contactbody import meshes
    triangles = meshes.rectangle(tmp_path / "rect.msh", nx=4, ny=4)
    inst = Instance(md3d, unzipped3d)
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setString([next(v.valueReference for v in md3d.modelVariables if v.name == "mesh")],
                   [str(triangles)])
    with pytest.raises(FMICallException):
        inst.exitInitializationMode()
    assert "holds triangles, a 2D body" in inst.text()
    inst.close()
    with zipfile.ZipFile(FMU3D) as z:
        (tmp_path / "block.msh").write_bytes(z.read("resources/block.msh"))
    md2 = fmpy.read_model_description(str(FMU))
    two = Instance(md2, fmpy.extract(str(FMU)))
    two.setupExperiment(startTime=0)
    two.enterInitializationMode()
    two.setString([next(v.valueReference for v in md2.modelVariables if v.name == "mesh")],
                  [str(tmp_path / "block.msh")])
    with pytest.raises(FMICallException):
        two.exitInitializationMode()
    assert "holds tetrahedra, a 3D body" in two.text()
    two.close()


def steps(inst, vr, t0, count, names):
    rows = []
    for k in range(count):
        inst.doStep(t0 + k * H, H)
        rows.append([x.hex() for x in inst.getReal([vr[n] for n in names])])
    return rows


def test_state_save_restore_serialize_and_reset(unzipped3d, md3d):
    """A state taken mid-run, restored (also from its serialized bytes), gives the same outputs
    bit for bit; a reset run repeats the first; the 2D model's bytes are refused."""
    vr = {v.name: v.valueReference for v in md3d.modelVariables}
    names = ["energy", "friction_force", "friction_force_z", "top_reaction_z", "friction_work"]
    inst = Instance(md3d, unzipped3d)

    def start():
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setReal([vr["foundation_velocity_z"], vr["friction_coefficient"]], [8.0, 0.6])
        inst.exitInitializationMode()

    start()
    first = steps(inst, vr, 0, 4, names)
    state = inst.getFMUstate()
    blob = inst.serializeFMUstate(state)
    later = steps(inst, vr, 4 * H, 4, names)
    inst.setFMUstate(state)
    assert steps(inst, vr, 4 * H, 4, names) == later
    inst.setFMUstate(inst.deSerializeFMUstate(blob))
    assert steps(inst, vr, 4 * H, 4, names) == later
    inst.freeFMUstate(state)
    inst.reset()
    start()
    assert steps(inst, vr, 0, 4, names) == first

    md2 = fmpy.read_model_description(str(FMU))
    two = Instance(md2, fmpy.extract(str(FMU)))
    two.setupExperiment(startTime=0)
    two.enterInitializationMode()
    two.exitInitializationMode()
    planar_blob = two.serializeFMUstate(two.getFMUstate())
    two.close()
    with pytest.raises(FMICallException):
        inst.deSerializeFMUstate(planar_blob)
    assert "not a ContactBody3D state" in inst.text()
    inst.close()


def test_field_output_and_edge_history_carry_z(tmp_path):
    """The .vtu files hold tetrahedra (VTK type 10); the edge history's records have z,
    friction_z and slip_velocity_z, and its last record equals the FMI 3.0 arrays."""
    names = ["edge_friction_z", "edge_slip_velocity_z", "edge_z", "edge_pressure"]
    r = fmpy.simulate_fmu(str(FMU3D_FMI3), stop_time=5e-4, output_interval=H, output=names,
                          start_values={"result_directory": str(tmp_path), "edge_output_interval": H,
                                        "field_output_interval": 2e-4, "foundation_velocity_z": 10.0,
                                        "friction_coefficient": 0.5})
    history = np.load(tmp_path / "contactbody_edge.npy")
    assert {"z", "friction_z", "slip_velocity_z"} <= set(history.dtype.names)
    assert len(history) == len(r)
    for field, name in [("friction_z", "edge_friction_z"), ("slip_velocity_z", "edge_slip_velocity_z"),
                        ("z", "edge_z"), ("pressure", "edge_pressure")]:
        assert np.array_equal(history[field][-1], r[name][-1]), field
    assert np.abs(history["friction_z"][-1]).max() > 0
    vtu = sorted(tmp_path.glob("*.vtu"))
    assert vtu
    text = vtu[-1].read_text()
    encoded = re.search(r'Name="types"[^>]*>([^<]*)<', text).group(1).strip()
    types = base64.b64decode(encoded)[8:]  # a UInt64 byte count, then one UInt8 per cell
    assert len(types) == 6 * 6 ** 3 and set(types) == {10}


def test_von_mises_of_a_tetrahedron_under_uniaxial_strain():
    """u = e x along x: sigma = diag(lam e + 2 mu e, lam e, lam e), whose von Mises stress is
    2 mu e, whatever the tetrahedron."""
    from contactbody import fields
    points = np.array([[0, 0, 0], [1, 0.1, 0], [0.2, 1, 0.1], [0.1, 0.3, 1.0]])
    e, lam, mu = 1e-3, 300e6, 150e6
    u = np.zeros_like(points)
    u[:, 0] = e * points[:, 0]
    stress = fields.von_mises_solid(points, np.array([[0, 1, 2, 3]]), u, lam, mu)
    assert stress[0] == pytest.approx(2 * mu * e, rel=1e-12)
    faces, owner = fields.boundary_faces(np.array([[0, 1, 2, 3], [1, 2, 3, 4]]))
    assert len(faces) == 6 and sorted(owner) == [0, 0, 0, 1, 1, 1]


@pytest.mark.skipif(SANITIZED, reason="the example runs build/'s FMU, not the sanitized one: the main job's")
def test_turning_pad_example_measures_what_it_draws(tmp_path):
    """examples/turning_pad_3d.py on an 8 mm mesh: the picture is written, the energy balance
    closes, in mid-turn some nodes stick and some slip, the friction's heading lags the
    foundation's while it turns and every node ends slipping at F x its pressure."""
    subprocess.run([sys.executable, str(ROOT / "examples" / "turning_pad_3d.py"), "--out", str(tmp_path),
                    "--size", "8e-3"], check=True, capture_output=True, cwd=ROOT / "examples")
    summary = json.loads((tmp_path / "turning_pad_3d.json").read_text())
    assert (tmp_path / "turning_pad_3d.png").stat().st_size > 50_000
    assert summary["energy_balance_residual"] < 1e-9
    assert summary["mid_turn_nodes"]["stick"] > 0 and summary["mid_turn_nodes"]["slip"] > 0
    assert summary["largest_heading_lag_during_turn_deg"] > 10
    assert summary["friction_over_F_normal_at_end"] == pytest.approx(1, abs=1e-2)


def test_the_reduced_pad_that_is_slower_than_the_full_one_is_warned_about(tmp_path, unzipped3d):
    """The turning pad at 4 mm cells (188 contact nodes, 564 contact unknowns): its reduced body
    of 40 modes took 1.15 times the full body's CPU time in benchmarks/results/turning_pad.md,
    and the initialization says so, naming modes = 0; the full body is not warned about."""
    from conftest import fmu_log
    from contactbody import meshes
    path = meshes.pad3d(tmp_path / "pad.msh", size=4e-3)

    def warned(modes):
        error, messages = fmu_log({"mesh": str(path), "modes": modes, "friction_coefficient": 0.5,
                                   "damping_stiffness": 2e-6}, unzipped3d)
        assert error is None, error
        return [m for m in messages if "on a long contact edge" in m]
    long_edge = warned(40)
    assert len(long_edge) == 1 and "564 contact unknowns" in long_edge[0], long_edge
    assert "consider modes = 0" in long_edge[0]
    assert not warned(0)


def test_the_controller_weighs_a_new_factorization_before_doubling_its_span(unzipped3d, md3d):
    """The block falls onto the foundation under tolerance = 1e-2 (decisions.md, "Substeps
    chosen by a tolerance"). Once the estimate allows doubling the span, the doubled span's
    factorization (about 30 solves on this block) is not made at once: the log says the pairs
    kept their span and what the operator costs. After enough declined doublings have forgone
    that many substeps, the span doubles, and the steps take fewer substeps."""
    inst = Instance(md3d, unzipped3d, "weigh")
    inst.setDebugLogging(True, [])
    vr = {v.name: v.valueReference for v in md3d.modelVariables}
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.set_values({"friction_coefficient": 0.0, "foundation_velocity": 0.0, "top_control": 1,
                     "top_force": 0.0, "initial_gap": 1e-4, "initial_velocity_y": -1.0,
                     "damping_stiffness": 4e-6, "internal_step": H, "tolerance": 1e-2})
    inst.exitInitializationMode()
    substeps, kept = [], []
    for k in range(30):
        before = len(inst.messages)
        inst.doStep(k * H, H)
        substeps.append(inst.getInteger([vr["substeps"]])[0])
        kept.append(any("kept their span" in m[2] for m in inst.messages[before:]))
    messages = [m[2] for m in inst.messages if "kept their span" in m[2]]
    inst.close()
    assert messages and re.search(r"costs about [0-9.]+ solves", messages[0]), messages
    cost = float(re.search(r"costs about ([0-9.]+) solves", messages[0]).group(1))
    assert cost > 6  # more than one declined doubling forgoes
    first = kept.index(True)
    assert sum(kept) * 6 >= cost  # declined until the forgone substeps reached the cost
    assert min(substeps[first + 1:]) < substeps[first], substeps


@pytest.mark.skipif(SANITIZED, reason="dask workers do not load the sanitized FMU (as test_study.py)")
def test_a_study_runs_on_the_3d_body_with_its_units(tmp_path):
    """contactbody.study on ContactBody3D: two points sliding along x and along z; the z
    friction has its metric, the apparent friction ratio is the mean force's magnitude, and
    study.json records N and J."""
    from contactbody.study import Study, run_study
    study = Study(stop_time=5e-4, output_interval=1e-4, average_from=2e-4,
                  fixed={"damping_stiffness": 2e-6, "friction_coefficient": 0.3},
                  grid={"foundation_velocity_z": [0.0, 5.0]}, series=["friction_force_z"])
    df = run_study(study, tmp_path, fmu=FMU3D, workers=1, progress=False, dashboard=False)
    assert list(df["status"]) == ["ok", "ok"]
    along_x, along_z = (df[df["foundation_velocity_z"] == v].iloc[0] for v in (0.0, 5.0))
    assert abs(along_x["friction_force_z_mean"]) < 1e-3 * abs(along_x["friction_force_mean"])
    assert along_z["friction_force_z_mean"] > 0
    assert along_z["apparent_friction_ratio"] == pytest.approx(
        np.hypot(along_z["friction_force_mean"], along_z["friction_force_z_mean"])
        / along_z["normal_force_mean"], rel=1e-12)
    assert 0.25 < along_z["apparent_friction_ratio"] <= 0.3 * (1 + 1e-9)
    units = json.loads((tmp_path / "study.json").read_text())["units"]
    assert (units["normal_force_mean"], units["energy_final"], units["friction_power"]) == ("N", "J", "W")


# ---- the supernodal factor's kernels: the fastest this CPU has, or the baseline ----

@pytest.mark.skipif(SANITIZED, reason="a 7,803-unknown factor under the sanitizers takes minutes")
def test_the_fast_kernels_agree_with_the_baseline_and_the_log_names_them(unzipped3d, tmp_path):
    """A hemisphere of 2.7k nodes pressed from the static start: its factor is supernodal (1.1e9
    flops). The log names the kernel set (`baseline` when baseline_kernels = 1); the outputs of
    the fastest kernels agree with the baseline's to 1e-10 relative."""
    from contactbody import meshes
    from conftest import fmu_log
    mesh = meshes.hemisphere(tmp_path / "hemisphere.msh", radius=0.05, contact_size=5e-4,
                             far_size=1e-2, fine_distance=0.0045, refine_distance=0.025,
                             contact_angle=25.0)
    scene = {"mesh": str(mesh), "friction_coefficient": 0.0, "initial_state": 1,
             "top_displacement": -2e-4, "internal_step": 1e-6, "damping_stiffness": 4e-6}
    outputs = ["normal_force", "strain_energy", "kinetic_energy", "top_reaction_y", "energy"]
    runs = {}
    for baseline in (1, 0):
        error, log = fmu_log({**scene, "baseline_kernels": baseline}, unzipped3d)
        assert error is None, error
        line = next(m for m in log if m.startswith("contact solve:"))
        kernels, threads = line.split("flops of factorization): ")[1].rsplit(", ", 1)
        assert kernels == ("baseline" if baseline else fastest_kernels_of_this_cpu()), line
        assert threads == "1 thread", line
        assert line.startswith("contact solve: sparse"), line
        runs[baseline] = simulate(stop=3e-4, output=outputs, **scene, baseline_kernels=baseline)
    for name in outputs:  # each against its own size; the kinetic energy against the energy's
        a, b = runs[1][name], runs[0][name]
        scale = np.abs(runs[1]["energy" if name == "kinetic_energy" else name]).max()
        assert scale > 0, name
        assert np.abs(a - b).max() <= 1e-10 * scale, (name, np.abs(a - b).max() / scale)


@pytest.mark.skipif(SANITIZED, reason="a 7,803-unknown factor under the sanitizers takes minutes")
def test_two_threads_give_the_outputs_of_one_bit_for_bit(unzipped3d, tmp_path):
    """The same hemisphere (its factor supernodal, refactored as its held set changes), pressed
    and sliding, on one thread and on two: every output equal bit for bit, and the log says how
    many threads ran."""
    from contactbody import meshes
    from conftest import fmu_log
    mesh = meshes.hemisphere(tmp_path / "hemisphere.msh", radius=0.05, contact_size=5e-4,
                             far_size=1e-2, fine_distance=0.0045, refine_distance=0.025,
                             contact_angle=25.0)
    scene = {"mesh": str(mesh), "friction_coefficient": 0.3, "initial_state": 1,
             "top_displacement": -2e-4, "internal_step": 1e-6, "foundation_velocity": 1.0}
    outputs = ["normal_force", "friction_force", "friction_force_z", "strain_energy",
               "friction_dissipation", "top_reaction_y", "energy", "substeps"]
    runs = {}
    for threads in (1, 2):
        error, log = fmu_log({**scene, "threads": threads}, unzipped3d)
        assert error is None, error
        line = next(m for m in log if m.startswith("contact solve:"))
        assert line.endswith(f", {threads} thread" + ("s" if threads > 1 else "")), line
        runs[threads] = simulate(stop=1e-4, output=outputs, **scene, threads=threads)
    assert np.abs(runs[1]["normal_force"]).max() > 0 and np.abs(runs[1]["friction_force"]).max() > 0
    for name in outputs:
        assert np.array_equal(runs[1][name], runs[2][name]), name


def test_a_state_whose_factor_holds_sliding_nodes_replays_bit_for_bit(unzipped3d, md3d, tmp_path):
    """A damped hemisphere sliding at F = 0.3 (its factor supernodal, its slipping nodes' rows held in
    the factor's LU along their slip directions): a state taken mid-run carries those
    directions (the bytes' last field is not empty), and restored, also from its bytes, it gives
    the same outputs bit for bit."""
    import struct
    from contactbody import meshes
    mesh = meshes.hemisphere(tmp_path / "hemisphere.msh", radius=0.05, contact_size=5e-4,
                             far_size=1e-2, fine_distance=0.0045, refine_distance=0.025,
                             contact_angle=25.0)
    vr = {v.name: v.valueReference for v in md3d.modelVariables}
    names = ["normal_force", "friction_force", "friction_force_z", "energy", "friction_dissipation"]
    inst = Instance(md3d, unzipped3d)
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setString([vr["mesh"]], [str(mesh)])
    inst.setInteger([vr["initial_state"]], [1])
    inst.setReal([vr[n] for n in ("friction_coefficient", "top_displacement", "internal_step",
                                  "foundation_velocity", "foundation_velocity_z", "damping_stiffness")],
                 [0.3, -2e-4, 1e-6, 12.0, 16.0, 4e-6])
    inst.exitInitializationMode()
    h = 2e-5
    for k in range(3):
        inst.doStep(k * h, h)
    state = inst.getFMUstate()
    blob = inst.serializeFMUstate(state)
    end = len(blob) - 16  # the last fields: the controller's substep and declined savings
    def held_slips(k):  # k doubles at the end after their count, after the nodes' pattern
        at = end - 8 * k - 8
        nodes = k // 2
        return (k % 2 == 0 and struct.unpack_from("<Q", blob, at)[0] == k and
                struct.unpack_from("<Q", blob, at - nodes - 8)[0] == nodes)
    slips = next(k for k in range(2, len(blob) // 8, 2) if held_slips(k))
    directions = struct.unpack_from(f"<{slips}d", blob, end - 8 * slips)
    assert sum(x != 0 for x in directions) > 100  # the slipping nodes' directions, x then z
    later = []
    for k in range(3, 6):
        inst.doStep(k * h, h)
        later.append([x.hex() for x in inst.getReal([vr[n] for n in names])])
    assert abs(inst.getReal([vr["friction_force"]])[0]) > 0
    for restore in (lambda: state, lambda: inst.deSerializeFMUstate(blob)):
        inst.setFMUstate(restore())
        again = []
        for k in range(3, 6):
            inst.doStep(k * h, h)
            again.append([x.hex() for x in inst.getReal([vr[n] for n in names])])
        assert again == later
    inst.freeFMUstate(state)
    inst.close()
