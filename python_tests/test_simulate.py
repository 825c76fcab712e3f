"""The default scene through fmpy's master and the physics of the paper's
Figs. 7-8."""
import numpy as np
import pytest
from fmpy import simulate_fmu

OUTPUTS = ["energy", "kinetic_energy", "strain_energy", "friction_work",
           "energy_minus_friction_work", "normal_force", "friction_force", "corner_pressure",
           "corner_friction", "top_reaction_x", "top_reaction_y", "active_contact_nodes",
           "slipping_contact_nodes", "max_penetration"]


def simulate(fmu_path, stop_time=0.02, output_interval=1e-4, **start_values):
    return simulate_fmu(fmu_path, stop_time=stop_time, output_interval=output_interval,
                        start_values=start_values, output=OUTPUTS)


@pytest.mark.parametrize("variant", [0, 1, 2, 3])
def test_default_scene_gives_every_output_finite(fmu_path, variant):
    r = simulate(fmu_path, mass_matrix=variant)
    assert r["time"][-1] == pytest.approx(0.02)
    assert len(r) == 201
    for name in OUTPUTS:
        assert np.all(np.isfinite(r[name])), name
    assert r["energy"][0] == pytest.approx(0.1875, rel=1e-12)  # E(0) of the paper's initial state
    assert r["friction_work"][0] == 0
    np.testing.assert_allclose(r["energy"], r["kinetic_energy"] + r["strain_energy"], rtol=1e-12)
    np.testing.assert_allclose(r["energy_minus_friction_work"], r["energy"] - r["friction_work"],
                               rtol=1e-9, atol=1e-9 * np.abs(r["energy"]).max())
    # Averages of forces that obey the contact law obey it too.
    assert np.all(r["normal_force"] >= 0)
    assert np.all(np.abs(r["friction_force"]) <= 1.2 * r["normal_force"] * (1 + 1e-9) + 1e-9)
    assert np.all(r["slipping_contact_nodes"] <= r["active_contact_nodes"])
    assert np.all(r["active_contact_nodes"] <= 21)
    assert r["active_contact_nodes"][1:].max() > 0
    assert np.all(r["max_penetration"] >= 0)
    # The foundation drags the body forward: friction pushes +x and does work on it.
    assert r["friction_force"][1] > 0 and r["friction_work"][1] > 0
    if variant == 3:  # contact imposed at the end of each step: no penetration at all
        assert r["max_penetration"].max() <= 1e-12


def max_energy(fmu_path, variant, dt):
    return simulate(fmu_path, mass_matrix=variant, internal_step=dt)["energy"].max()


def test_standard_scheme_gets_worse_as_the_step_shrinks_while_redistribution_stays_bounded(fmu_path):
    """Paper Fig. 7: with the standard mass the largest energy over 0.02 s grows by more than
    100x from dt = 4e-6 to 1e-6; with the normal-only redistribution it stays within 10x."""
    standard = max_energy(fmu_path, 0, 1e-6) / max_energy(fmu_path, 0, 4e-6)
    redistributed = max_energy(fmu_path, 1, 1e-6) / max_energy(fmu_path, 1, 4e-6)
    assert standard > 100
    assert 0.1 < redistributed < 10


@pytest.mark.parametrize("variant", [1, 2])
def test_without_friction_and_sliding_energy_is_conserved(fmu_path, variant):
    r = simulate(fmu_path, stop_time=0.005, mass_matrix=variant, friction_coefficient=0.0,
                 foundation_velocity=0.0)
    e = r["energy_minus_friction_work"]
    assert np.all(r["friction_work"] == 0)
    assert (e.max() - e.min()) / e[0] < 0.01
    assert r["active_contact_nodes"].max() > 0  # contact was part of the motion


def test_instances_share_nothing(model_description, unzipped):
    """Two instances stepped alternately give what each gives alone."""
    from conftest import Instance
    vr = {v.name: v.valueReference for v in model_description.modelVariables}

    def start(name, F):
        inst = Instance(model_description, unzipped, name)
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setReal([vr["friction_coefficient"]], [F])
        inst.exitInitializationMode()
        return inst

    def run(insts, steps=20):
        out = {id(i): [] for i in insts}
        for k in range(steps):
            for i in insts:
                i.doStep(k * 1e-4, 1e-4)
                out[id(i)].append(i.getReal([vr["energy"], vr["friction_force"]]))
        return [np.array(out[id(i)]) for i in insts]

    a, b = start("a", 1.2), start("b", 0.3)
    together = run([a, b])
    alone = run([start("c", 1.2)]) + run([start("d", 0.3)])
    np.testing.assert_array_equal(together[0], alone[0])
    np.testing.assert_array_equal(together[1], alone[1])
    assert not np.array_equal(together[0], together[1])
