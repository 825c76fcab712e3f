"""The sparse contact solve through the FMU (issue 54): a pad whose contact faces are refined
to about 400 contact nodes takes it (the log says so), and every variant keeps what the
condensed solve gave: the energy balance to 1e-9, friction that dissipates, static friction,
the static start, and force control's balance at t0; a state saved on slipping rows replays."""
import numpy as np
import pytest

from contactbody import meshes
from contactbody.fmu import Instance, Model
from test_energy_balance import WORKS, check_balance

SCENE = {"initial_state": 1, "friction_coefficient": 0.3, "static_friction_ratio": 1.5,
         "damping_stiffness": 4e-6, "internal_step": 1e-6, "foundation_velocity": 20.0,
         "top_displacement": -5e-6}


@pytest.fixture(scope="module")
def pad(tmp_path_factory):
    path = tmp_path_factory.mktemp("pad") / "pad.msh"
    return str(meshes.pad(path, width=0.08, size=2e-3, contact_size=0.066 / 398))


def logged_model(fmu_path):
    model = Model(fmu_path, name="sparse")
    model.instance.close()
    model.instance = Instance(model.description, model.directory, "sparse", logging_on=True)
    return model


def contact_solve(model):
    return [m[2] for m in model.instance.messages if m[2].startswith("contact solve:")]


@pytest.mark.parametrize("variant", [0, 1, 2, 3, 4])
def test_every_variant_closes_its_energy_balance_on_the_sparse_solve(fmu_path, pad, variant):
    model = logged_model(fmu_path)
    try:
        rows, _ = model.run({**SCENE, "mesh": pad, "mass_matrix": variant}, 3e-4, 3e-5, WORKS)
        assert contact_solve(model)[0].startswith("contact solve: sparse"), contact_solve(model)
    finally:
        model.close()
    series = [dict(zip(WORKS, values)) for values in zip(*(rows[n] for n in WORKS))]
    check_balance(series[0], series[1:], variant, "constant", SCENE["friction_coefficient"],
                  SCENE["damping_stiffness"])


def test_force_control_starts_in_balance_on_the_sparse_solve(fmu_path, pad):
    model = logged_model(fmu_path)
    try:
        rows, _ = model.run({**SCENE, "mesh": pad, "top_control": 1, "top_force": 9000.0},
                            6e-5, 3e-5, ["normal_force", "top_reaction_y", "active_contact_nodes"])
        assert contact_solve(model)[0].startswith("contact solve: sparse")
    finally:
        model.close()
    assert rows["normal_force"][0] == pytest.approx(9000.0, rel=1e-10)
    assert rows["normal_force"][0] == pytest.approx(-rows["top_reaction_y"][0], rel=1e-10)
    assert np.all(rows["active_contact_nodes"] > 300)


def test_a_serialized_state_on_slipping_rows_replays_bit_for_bit(fmu_path, pad):
    """The saved factor pattern says which nodes the factor holds slipping (+-3): sliding on
    the pad, a state serialized mid-run and restored into a second instance replays the first
    instance's outputs bit for bit."""
    names = ["normal_force", "friction_force", "kinetic_energy", "strain_energy"]

    def steps(model, t0, count):
        vrs = [model.variable(n).valueReference for n in names]
        rows = []
        for k in range(count):
            model.instance.doStep(t0 + k * 1e-5, 1e-5)
            rows.append(model.instance.getReal(vrs))
        return rows

    first, second = Model(fmu_path, name="saving"), Model(fmu_path, name="restoring")
    try:
        first.start({**SCENE, "mesh": pad})
        steps(first, 0.0, 3)
        blob = first.instance.serializeFMUstate(first.instance.getFMUstate())
        expected = steps(first, 3e-5, 3)
        second.start({**SCENE, "mesh": pad})
        second.instance.setFMUstate(second.instance.deSerializeFMUstate(blob))
        assert steps(second, 3e-5, 3) == expected
    finally:
        first.close()
        second.close()
