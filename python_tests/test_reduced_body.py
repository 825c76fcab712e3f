"""The reduced body through the FMU (modes > 0, docs/reduced_body.md): with every finite mode it
is the full body; with few its own energy balance closes; its state saves, restores and
serializes; a reset keeps its basis; its field output is its state on every node; under force
control the plate's translation joins its coordinates; what it cannot do is refused by name."""
import pathlib

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.fmi1 import FMICallException

from conftest import Instance

from contactbody import fields

H = 1e-4
# Friction, Rayleigh damping, an initial velocity, the clamp pressing on: nothing is trivial.
SCENE = dict(nx=6, ny=6, friction_coefficient=0.3, damping_mass=20.0, damping_stiffness=4e-6,
             initial_velocity_x=0.5, internal_step=2e-6, foundation_velocity=20.0)
REALS = ["energy", "kinetic_energy", "strain_energy", "friction_work", "normal_force",
         "friction_force", "corner_pressure", "corner_friction", "top_reaction_x",
         "top_reaction_y", "max_penetration", "damping_work", "clamp_work",
         "normal_contact_work", "friction_dissipation", "foundation_work", "top_position",
         "top_velocity"]


def finite_modes(nx, ny, variant, edge=0):
    """Free dofs (every node but the top row, x and y) less the massless ones: the bottom
    edge's normal dofs where M_r redistributes (1, 2, 4), and its tangential ones too (2); with
    the tangential-mass edge (reduced_edge = 2, the default for variants 0, 3, 4) less the
    edge's x dofs too, which are coordinates of their own."""
    free = 2 * (nx + 1) * ny
    massless = {0: 0, 1: 1, 2: 2, 3: 0, 4: 1}[variant] * (nx + 1)
    tangential = edge == 2 or (edge == 0 and variant in (0, 3, 4))
    return free - massless - (nx + 1 if tangential else 0)


def start(md, unzipped, values, name="reduced"):
    vr = {v.name: v.valueReference for v in md.modelVariables}
    types = {v.name: v.type for v in md.modelVariables}
    inst = Instance(md, unzipped, name)
    inst.setDebugLogging(True, ["logEvents"])
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    for k, v in values.items():
        (inst.setReal if types[k] == "Real" else inst.setInteger)([vr[k]], [v])
    inst.exitInitializationMode()
    return inst, vr


def run(inst, vr, k0, k1, pressed=False):
    """Steps k0..k1-1 of H, the clamp pressing on at 1 mm/s and by a jump each step (or, with
    `pressed`, under force control, the force rising by 1e4 N/m a step); the outputs."""
    rows = []
    for k in range(k0, k1):
        if pressed:
            inst.setReal([vr["top_force"]], [3e5 + 1e4 * k])
        else:
            inst.setReal([vr["top_displacement"]], [-2.5e-5 - 2e-7 * k])
            inst.setRealInputDerivatives([vr["top_displacement"]], [1], [-1e-3])
        inst.doStep(k * H, H)
        rows.append(inst.getReal([vr[n] for n in REALS]))
    return np.array(rows)


def balance_of(rows, e0):
    """E - E(0) - (clamp + normal_contact + friction - damping) after each step, and the
    outputs by name."""
    col = {n: rows[:, i] for i, n in enumerate(REALS)}
    return (col["energy"] - e0 - col["clamp_work"] - col["normal_contact_work"]
            - col["friction_work"] + col["damping_work"]), col


@pytest.mark.parametrize("variant, edge", [(1, 0), (2, 0), (4, 0), (1, 2), (4, 1)])
def test_every_mode_gives_the_full_body(model_description, unzipped, variant, edge):
    """500 substeps (10 steps of 50): every real output equals the full body's to 1e-10 of
    its largest value, with either contact edge (edge 0: the variant's default). Variants 0 and
    3 put mass on the contact dofs, where the full body itself turns a 1e-14 change into one of
    order one (tests_cpp/test_reduced_stepper.cpp)."""
    scene = {**SCENE, "mass_matrix": variant}
    full, vr = start(model_description, unzipped, scene, "full")
    reduced, _ = start(model_description, unzipped,
                       {**scene, "modes": finite_modes(6, 6, variant, edge), "reduced_edge": edge})
    expected, got = run(full, vr, 0, 10), run(reduced, vr, 0, 10)
    full.close()
    reduced.close()
    assert np.abs(expected).max(axis=0).min() > 0  # every output moved
    # Each output's largest value; max_penetration's is round-off where contact is imposed at
    # the end of the step (variant 4): against the clamp's displacement there.
    scale = np.abs(expected).max(axis=0)
    scale[REALS.index("max_penetration")] = max(scale[REALS.index("max_penetration")], 2.5e-5)
    worst = (np.abs(got - expected).max(axis=0) / scale).max()
    assert worst <= 1e-10, dict(zip(REALS, np.abs(got - expected).max(axis=0) / scale))


def test_more_modes_than_the_body_has_are_refused(model_description, unzipped):
    count = finite_modes(6, 6, 1)
    inst = Instance(model_description, unzipped)
    vr = {v.name: v.valueReference for v in model_description.modelVariables}
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setInteger([vr["nx"], vr["ny"], vr["modes"]], [6, 6, count + 1])
    with pytest.raises(FMICallException):
        inst.exitInitializationMode()
    assert any(f"has {count}" in m[2] or str(count) in m[2] for m in inst.messages), inst.messages
    inst.close()


# Force control: a plate of 10 kg/m pressed down by 3e5 N/m, the body falling at 0.3 m/s.
PLATE = dict(top_control=1, top_mass=10.0, initial_velocity_y=-0.3)


@pytest.mark.parametrize("variant", [1, 2, 4])
def test_every_mode_gives_the_full_body_under_force_control(model_description, unzipped,
                                                           variant):
    """Under force control the plate's translation is a coordinate beside the clamped body's
    modes: with all of them, every real output is the full body's to 1e-10 of its largest."""
    scene = {**SCENE, **PLATE, "mass_matrix": variant}
    full, vr = start(model_description, unzipped, scene, "full")
    reduced, _ = start(model_description, unzipped,
                       {**scene, "modes": finite_modes(6, 6, variant)})
    expected, got = run(full, vr, 0, 10, True), run(reduced, vr, 0, 10, True)
    full.close()
    reduced.close()
    moved = [n for n in REALS if n not in ("max_penetration",)]
    assert all(np.abs(expected[:, REALS.index(n)]).max() > 0 for n in moved)
    assert expected[-1, REALS.index("top_position")] < -1e-4  # the plate went down
    scale = np.abs(expected).max(axis=0)
    scale[REALS.index("max_penetration")] = max(scale[REALS.index("max_penetration")], 1e-4)
    # The works against the energy they balance: with contact on the midpoint (1, 2) the
    # normal contact work is round-off (5e-14 J/m of 700).
    for n in REALS:
        if n.endswith("_work") or n in ("friction_dissipation",):
            scale[REALS.index(n)] = max(scale[REALS.index(n)], scale[REALS.index("energy")])
    worst = np.abs(got - expected).max(axis=0) / scale
    assert worst.max() <= 1e-10, dict(zip(REALS, worst))


@pytest.mark.parametrize("variant", [1, 4])
def test_energy_balance_closes_under_force_control(model_description, unzipped, variant):
    """8 modes and the plate: E (with the plate's kinetic energy) - E(0) = the top force's
    work + normal_contact + friction - damping to 1e-9 of the largest energy, every step."""
    scene = {**SCENE, **PLATE, "mass_matrix": variant, "modes": 8}
    inst, vr = start(model_description, unzipped, scene)
    e0 = inst.getReal([vr["energy"]])[0]
    rows = run(inst, vr, 0, 10, True)
    inst.close()
    balance, col = balance_of(rows, e0)
    # The top force's work is far above the balance's tolerance: leaving it out would show.
    assert col["normal_force"].max() > 0
    assert np.abs(col["clamp_work"]).max() > 1e-3 * col["energy"].max()
    assert np.abs(balance).max() <= 1e-9 * max(e0, col["energy"].max())


def test_static_start_under_force_control_is_exact_with_few_modes(model_description, unzipped):
    """The static state under the plate's force is the edge's static response, which the basis
    holds exactly (its residual attachment modes and the translation): with 8 modes the
    initial outputs are the full body's to 1e-10."""
    scene = {**SCENE, **PLATE, "initial_velocity_x": 0.0, "initial_velocity_y": 0.0,
             "initial_state": 1, "top_force": 3e5, "initial_gap": 1e-5}
    names = ["normal_force", "friction_force", "top_position", "strain_energy", "energy",
             "top_reaction_y", "corner_pressure"]
    full, vr = start(model_description, unzipped, scene, "full")
    reduced, _ = start(model_description, unzipped, {**scene, "modes": 8})
    expected = np.array(full.getReal([vr[n] for n in names]))
    got = np.array(reduced.getReal([vr[n] for n in names]))
    full.close()
    reduced.close()
    assert expected[names.index("normal_force")] == pytest.approx(3e5, rel=1e-9)
    assert np.all(np.abs(expected[[0, 2, 3, 4, 5, 6]]) > 0)
    assert np.all(np.abs(got - expected) <= 1e-10 * np.abs(expected).max()), dict(
        zip(names, np.abs(got - expected) / np.abs(expected)))


@pytest.mark.parametrize("variant", range(5))
def test_energy_balance_closes_with_few_modes(model_description, unzipped, variant):
    """8 modes, friction with a slip-rate law, damping: E - E(0) = clamp + normal_contact +
    friction - damping to 1e-9 of the largest energy, every step."""
    scene = {**SCENE, "mass_matrix": variant, "modes": 8, "stribeck_velocity": 0.5,
             "static_friction_ratio": 1.5, "viscous_friction": 0.01}
    inst, vr = start(model_description, unzipped, scene)
    e0 = inst.getReal([vr["energy"]])[0]
    rows = run(inst, vr, 0, 10)
    inst.close()
    balance, col = balance_of(rows, e0)
    assert col["normal_force"].max() > 0 and col["damping_work"][-1] > 0
    assert np.abs(balance).max() <= 1e-9 * max(e0, col["energy"].max())


def test_state_restores_and_serializes_bit_for_bit(model_description, unzipped):
    inst, vr = start(model_description, unzipped, {**SCENE, "modes": 8})
    run(inst, vr, 0, 3)
    saved = inst.getFMUstate()
    later = run(inst, vr, 3, 6)
    inst.setFMUstate(saved)
    assert np.array_equal(run(inst, vr, 3, 6), later)
    serialized = inst.serializeFMUstate(saved)
    inst.freeFMUstate(saved)
    other, _ = start(model_description, unzipped, {**SCENE, "modes": 8}, "other")
    state = other.deSerializeFMUstate(serialized)
    other.setFMUstate(state)
    assert np.array_equal(run(other, vr, 3, 6), later)
    other.freeFMUstate(state)
    other.close()
    # A state of the reduced body does not fit the full body: refused, not misread.
    full, _ = start(model_description, unzipped, SCENE, "full")
    with pytest.raises(FMICallException):
        full.setFMUstate(full.deSerializeFMUstate(serialized))
    assert any("modes" in m[2] for m in full.messages), full.messages
    full.close()
    inst.close()


def test_state_restores_bit_for_bit_where_the_contact_factorization_is_updated(
        model_description, unzipped):
    """At nx = 80 the reduced body updates its contact factorization when a few nodes change
    state (Woodbury), so a step's last bits depend on the pattern it was factored at: the
    state keeps it. Restored at each of several points, in the same instance and through the
    bytes in another, the run repeats the saved one bit for bit (before the state kept it, the
    one saved after 7 steps did not, by 4e-9)."""
    scene = {**SCENE, "nx": 80, "ny": 80, "modes": 40}
    inst, vr = start(model_description, unzipped, scene)
    other, _ = start(model_description, unzipped, scene, "other")
    run(inst, vr, 0, 3)
    for k in range(3, 11):
        saved = inst.getFMUstate()
        later = run(inst, vr, k, k + 2)
        serialized = inst.serializeFMUstate(saved)
        inst.setFMUstate(saved)
        assert np.array_equal(run(inst, vr, k, k + 2), later), k
        state = other.deSerializeFMUstate(serialized)
        other.setFMUstate(state)
        assert np.array_equal(run(other, vr, k, k + 2), later), k
        other.freeFMUstate(state)
        inst.setFMUstate(saved)
        run(inst, vr, k, k + 1)
        inst.freeFMUstate(saved)
    other.close()
    inst.close()


def test_reset_keeps_the_basis(model_description, unzipped):
    """The basis is built once: a reset and a rerun with other inputs and friction keep it
    (the log says so) and give a fresh instance's bits."""
    inst, vr = start(model_description, unzipped, {**SCENE, "modes": 8})
    assert any("basis built" in m[2] for m in inst.messages), inst.messages
    run(inst, vr, 0, 2)
    inst.reset()  # every variable back to its start value: the scene is set again
    inst.messages.clear()
    types = {v.name: v.type for v in model_description.modelVariables}
    changed = {"friction_coefficient": 0.2, "foundation_velocity": 5.0}
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    for k, v in {**SCENE, "modes": 8, **changed}.items():
        (inst.setReal if types[k] == "Real" else inst.setInteger)([vr[k]], [v])
    inst.exitInitializationMode()
    assert any("basis kept from the last run" in m[2] for m in inst.messages), inst.messages
    rerun = run(inst, vr, 0, 3)
    fresh, _ = start(model_description, unzipped, {**SCENE, "modes": 8, **changed}, "fresh")
    assert np.array_equal(run(fresh, vr, 0, 3), rerun)
    fresh.close()
    inst.close()


def test_field_output_is_the_state_on_every_node(fmu_path, tmp_path):
    """The .vtu files expand the reduced coordinates: their strain energy, computed from the
    field alone, is the strain_energy output (the reduced strain energy is exactly
    1/2 u^T A u of the expanded u)."""
    scene = dict(nx=8, ny=8, mass_matrix=0, internal_step=1e-5, modes=10,
                 result_directory=str(tmp_path), field_output_interval=2e-4)
    result = simulate_fmu(fmu_path, stop_time=2e-3, output_interval=1e-4, start_values=scene)
    snapshots = fields.read_collection(tmp_path / "contactbody.pvd")
    assert len(snapshots) == 11
    for t, path in snapshots:
        points, triangles, data = fields.read_field(path)
        k = int(np.argmin(np.abs(result["time"] - t)))
        strain = fields.strain_energy(points, triangles, data["displacement"], 300e6, 150e6)
        assert strain == pytest.approx(result["strain_energy"][k], rel=1e-9)


def test_fmi3_edge_arrays_of_every_mode_are_the_full_body_s():
    """The FMI 3.0 FMU's edge arrays (pressure, friction, slip velocity, gap, state) come from
    the same edge record: with every finite mode they equal the full body's to 1e-10."""
    from contactbody.fmu import find_fmu, simulate_fmi3
    fmu3 = pathlib.Path(find_fmu()).with_name("ContactBody_fmi3.fmu")
    scene = {k: v for k, v in SCENE.items() if k != "internal_step"}
    names = ["edge_pressure", "edge_friction", "edge_slip_velocity", "edge_gap"]
    runs = [simulate_fmi3(fmu3, start_values={**scene, **extra}, stop_time=1e-3,
                          output_interval=H, output=names + ["edge_state"])
            for extra in ({}, {"modes": finite_modes(6, 6, 1)})]
    for name in names:
        full, reduced = runs[0][name], runs[1][name]
        assert np.abs(full).max() > 0, name
        assert np.abs(reduced - full).max() <= 1e-10 * np.abs(full).max(), name
    assert np.array_equal(runs[0]["edge_state"], runs[1]["edge_state"])


def test_the_stability_warning_says_the_reduced_body_is_not_mapped(model_description, unzipped):
    """Undamped sliding with F = 0.3 lies in the measured unstable region: the full body's
    warning, and for the reduced body the same warning saying the map was measured on the
    full body."""
    scene = {**SCENE, "damping_mass": 0.0, "damping_stiffness": 0.0, "modes": 8}
    inst, _ = start(model_description, unzipped, scene)
    warnings = [m[2] for m in inst.messages if m[0] == 1]
    inst.close()
    assert any("measured unstable" in w and "modes = 8 has not been mapped" in w
               for w in warnings), warnings


@pytest.mark.parametrize("variant, ratio, edge", [(1, 1.0, 0), (3, 2.0, 1), (3, 2.0, 2), (4, 2.0, 0)])
def test_the_static_start_is_exact_with_few_modes(fmu_path, variant, ratio, edge):
    """The basis holds the edge's static response exactly (the residual attachment modes and
    the clamp's lift), so initial_state = static, a gap closed by the top included, gives the
    full body's initial reactions and energy to 1e-12 with 8 modes, with either edge. Static
    friction above kinetic makes the path decide which nodes stick (variant 3 holds a friction
    force of about 10 N/m at the start): the reduced body takes the full body's path (issue
    42, C: its own path gave E(0) 1.75e-3 off)."""
    values = dict(nx=6, ny=6, initial_state=1, initial_gap=1e-5, top_displacement=-3e-5,
                  friction_coefficient=0.3, damping_stiffness=4e-6, internal_step=2e-6,
                  mass_matrix=variant, static_friction_ratio=ratio, foundation_velocity=0.0)
    names = ["normal_force", "friction_force", "top_reaction_y", "energy", "strain_energy"]
    full, reduced = (simulate_fmu(fmu_path, stop_time=1e-4, output_interval=1e-4,
                                  start_values={**values, **extra}, output=names)
                     for extra in ({}, {"modes": 8, "reduced_edge": edge}))
    assert full["normal_force"][0] > 0
    for name in names:
        assert reduced[name][0] == pytest.approx(full[name][0], rel=1e-12, abs=1e-9), name


@pytest.mark.parametrize("variant", [0, 1, 2, 3, 4])
def test_t0_with_every_mode_is_the_full_bodys(model_description, unzipped, variant):
    """The paper's state at t = 0: the bottom nodes are on the foundation, in the reduced body
    too, whose heights are rebuilt from its coordinates to round-off (issue 42: variant 0 gave
    5000 N/m on 2 nodes against 15000 on 7)."""
    scene = {"nx": 6, "ny": 6, "mass_matrix": variant}
    full, vr = start(model_description, unzipped, scene, "full")
    reduced, _ = start(model_description, unzipped, {**scene, "modes": finite_modes(6, 6, variant)})
    try:
        f, r = (i.getReal([vr["normal_force"]])[0] for i in (full, reduced))
        assert f > 0 and r == pytest.approx(f, rel=1e-9)
        assert full.getInteger([vr["active_contact_nodes"]]) == reduced.getInteger([vr["active_contact_nodes"]]) == [7]
    finally:
        full.close()
        reduced.close()


def test_the_tangential_mass_edge_is_refused_where_the_variant_has_none(model_description, unzipped):
    inst = Instance(model_description, unzipped)
    vr = {v.name: v.valueReference for v in model_description.modelVariables}
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setInteger([vr["nx"], vr["ny"], vr["modes"], vr["mass_matrix"], vr["reduced_edge"]],
                    [6, 6, 8, 2, 2])
    with pytest.raises(FMICallException):
        inst.exitInitializationMode()
    assert any("redistributed_both has none" in m[2] for m in inst.messages), inst.messages
    inst.close()


# Issue 42's class A: a decreasing slip-rate law (F_s / F = 3 over 0.04 m/s), variant 4 on a
# 4 x 5 mesh. The full body runs it to 4 ms; the massless edge has no tangential mass, and its
# substeps then need not have one solution at any size (benchmarks/results/reduced_edge.md).
CLASS_A = {"nx": 4, "ny": 5, "mass_matrix": 4, "width": 0.02916, "height": 0.06328,
           "density": 564.5, "mu": 4.641e10, "lambda": 8.020e11, "friction_coefficient": 0.786,
           "static_friction_ratio": 2.997, "stribeck_velocity": 0.0397,
           "internal_step": 2.574e-5, "foundation_velocity": 7.433, "top_displacement": -2.324e-4}


def test_class_a_runs_with_the_tangential_mass_edge_and_the_massless_one_says_so(
        model_description, unzipped):
    """The tangential-mass edge (variant 4's default) runs the scene to 4 ms as the full body
    does. The massless edge is warned against at initialization, naming reduced_edge =
    tangential_mass; where its step fails, the error names it too, not 'reduce internal_step'."""
    for edge in (0, 1):
        inst, vr = start(model_description, unzipped, {**CLASS_A, "modes": 20, "reduced_edge": edge})
        advice = "reduced_edge = tangential_mass keeps the edge's tangential mass"
        warned = [m[2] for m in inst.messages if advice in m[2]]
        inst.setReal([vr["top_displacement"], vr["foundation_velocity"]],
                     [CLASS_A["top_displacement"], CLASS_A["foundation_velocity"]])
        failed = None
        try:
            for k in range(10):
                inst.doStep(k * 4e-4, 4e-4)
        except FMICallException:
            failed = [m[2] for m in inst.messages if "contact solve failed" in m[2]]
        inst.close()
        if edge == 0:
            assert failed is None and not warned
        else:
            assert warned, inst.messages
            assert failed is None or (failed and advice in failed[-1] and
                                      "Reduce internal_step" not in failed[-1]), failed
