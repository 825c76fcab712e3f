"""The force-driven top (scenes issue, item 1): a rigid plate of mass top_mass with u_x = 0,
pushed down by the input top_force; initial velocities; the static initial state; and the
scenes of item 4 (impact, lift-off and re-contact, reversal: examples/scenes.py)."""
import re
import sys

import fmpy
import numpy as np
import pytest
from fmpy.fmi2 import FMU2Slave

from conftest import ROOT, Instance

sys.path.insert(0, str(ROOT / "examples"))
from scenes import contact_intervals  # noqa: E402

WORKS = ["clamp_work", "normal_contact_work", "friction_work", "damping_work", "energy"]


@pytest.mark.parametrize("variant", [0, 1, 2, 3, 4])
@pytest.mark.parametrize("inputs", ["held", "ramped"])
def test_energy_balance_closes_with_the_plate(model_description, unzipped, vr, variant, inputs):
    """E (with the plate's kinetic energy) - E(0) = the top force's work on the plate +
    contact, friction and damping work, to 1e-9, under a force that varies step by step."""
    inst = Instance(model_description, unzipped, "plate")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setInteger([vr["nx"], vr["ny"], vr["mass_matrix"], vr["top_control"]],
                        [10, 10, variant, 1])
        inst.setReal([vr["friction_coefficient"], vr["damping_stiffness"], vr["top_mass"]],
                     [0.3, 4e-6, 2.0])
        inst.exitInitializationMode()
        refs = [vr[n] for n in WORKS]
        e0 = inst.getReal(refs)[-1]
        for k in range(40):
            t = k * 1e-4
            if inputs == "held":
                inst.setReal([vr["top_force"]], [2e4 * (1 + np.sin(3000 * t))])
            else:
                inst.setRealInputDerivatives([vr["top_force"]], [1], [6e7 * np.cos(3000 * t)])
            inst.doStep(t, 1e-4)
            clamp, normal, friction, damping, e = inst.getReal(refs)
            assert abs(e - e0 - (clamp + normal + friction - damping)) <= 1e-9 * max(abs(e), e0)
        assert clamp != 0
    finally:
        inst.close()


def impact(fmu_path, variant, dt, gap=1e-5):
    return fmpy.simulate_fmu(
        fmu_path, stop_time=1.5e-3, output_interval=1e-5,
        start_values={"mass_matrix": variant, "internal_step": dt, "friction_coefficient": 0.0,
                      "foundation_velocity": 0.0, "top_control": 1, "top_force": 0.0,
                      "top_displacement": 0.0, "initial_gap": gap, "initial_velocity_y": -1.0},
        output=["energy", "normal_force", "max_penetration", "top_position", "top_velocity"])


@pytest.mark.parametrize("variant", [1, 2, 4])
@pytest.mark.parametrize("dt", [4e-6, 1e-6])
def test_impact_keeps_the_energy_with_the_redistributed_mass(fmu_path, variant, dt):
    """The body (10 kg/m) and the plate (1 kg/m) fall at 1 m/s onto the foundation, F = 0, no
    top force. After the rebound the energy is within 1 % of before (measured: 1e-4 at most)
    and the contact force makes one interval, no chatter."""
    r = impact(fmu_path, variant, dt)
    e = r["energy"]
    assert e[0] == pytest.approx(5.5, rel=1e-12)  # 1/2 (10 + 1) 1^2
    assert abs(e[-1] / e[0] - 1) < 0.01
    assert contact_intervals(r["normal_force"]) == 1
    assert r["normal_force"][-1] == 0 and r["top_velocity"][-1] > 0  # bounced off


def test_impact_contrast_standard_and_implicit(fmu_path):
    """standard gains energy and chatters (measured: E x 7.4 and x 11, 2 and 3 contact
    intervals); standard_implicit_contact loses 1-3 % and keeps the integer steps out."""
    for dt in (4e-6, 1e-6):
        r = impact(fmu_path, 0, dt)
        assert r["energy"][-1] > 2 * r["energy"][0]
        assert contact_intervals(r["normal_force"]) >= 2
        r = impact(fmu_path, 3, dt)
        assert 0.95 < r["energy"][-1] / r["energy"][0] < 0.995
        assert r["max_penetration"].max() < 1e-15


def test_free_flight_before_the_impact(fmu_path):
    """With a gap of 0.1 mm the body flies at -1 m/s for 0.1 ms: no contact force, the plate
    moves rigidly with it."""
    r = impact(fmu_path, 1, 1e-6, gap=1e-4)
    flying = r["time"] < 9.5e-5
    assert np.all(r["normal_force"][flying] == 0)
    np.testing.assert_allclose(r["top_velocity"][flying], -1.0, rtol=1e-9)
    np.testing.assert_allclose(r["top_position"][flying], -r["time"][flying], rtol=1e-9,
                               atol=1e-15)


def test_a_constant_force_is_carried_by_the_foundation(fmu_path):
    """top_force = 15 kN/m on the paper's body (damped, F = 0): the plate's reaction and the
    contact force settle at 15 kN/m."""
    r = fmpy.simulate_fmu(fmu_path, stop_time=0.01, output_interval=1e-4,
                          start_values={"top_control": 1, "top_force": 15000.0,
                                        "friction_coefficient": 0.0, "foundation_velocity": 0.0,
                                        "damping_stiffness": 4e-6, "damping_mass": 200.0},
                          output=["normal_force", "top_reaction_y"])
    late = r["time"] > 0.005
    assert np.mean(r["normal_force"][late]) == pytest.approx(15000, rel=0.03)
    assert np.mean(r["top_reaction_y"][late]) == pytest.approx(-15000, rel=0.01)


@pytest.mark.parametrize("variant", [0, 1, 3, 4])
@pytest.mark.parametrize("friction", [0.0, 0.5])
def test_static_initial_state_stays_at_rest(fmu_path, variant, friction):
    """initial_state = static with the foundation at rest and a constant load: the body stays at
    rest, kinetic energy <= 1e-12 x strain energy over 0.01 s (measured <= 1.1e-15), and the
    outputs at t0 carry the preload that docs/user_guide.md quotes."""
    r = fmpy.simulate_fmu(fmu_path, stop_time=0.01, output_interval=1e-4,
                          start_values={"initial_state": 1, "foundation_velocity": 0.0,
                                        "friction_coefficient": friction, "mass_matrix": variant},
                          output=["kinetic_energy", "strain_energy", "normal_force",
                                  "top_reaction_y"])
    assert np.all(r["kinetic_energy"] <= 1e-12 * r["strain_energy"])
    assert r["normal_force"][0] > 1e4 and r["top_reaction_y"][0] == pytest.approx(
        -r["normal_force"][0], rel=1e-9)
    np.testing.assert_allclose(r["normal_force"], r["normal_force"][0], rtol=1e-6)
    quoted = re.search(r"preload on the default body is ([\d,]+) N/m at F = 0 and ([\d,]+) N/m "
                       r"at F = 0.5", (ROOT / "docs" / "user_guide.md").read_text().replace("\n", " "))
    preload = float(quoted.group(1 if friction == 0 else 2).replace(",", ""))
    assert round(float(r["normal_force"][0])) == preload  # as docs/user_guide.md says


@pytest.mark.parametrize("variant", [0, 1, 3, 4])
@pytest.mark.parametrize("friction", [0.0, 0.5])
@pytest.mark.parametrize("gap", [0.0, 2e-5])
def test_static_initial_state_under_force_control_stays_at_rest(fmu_path, variant, friction, gap):
    """top_control = force, initial_state = static, 15 kN/m on the plate, foundation at rest
    (with an initial gap, which the body starts closed on): the body and the plate stay at rest
    over 0.01 s, the foundation carries the force from t0."""
    r = fmpy.simulate_fmu(fmu_path, stop_time=0.01, output_interval=1e-4,
                          start_values={"initial_state": 1, "top_control": 1, "top_force": 15000.0,
                                        "foundation_velocity": 0.0, "top_displacement": 0.0,
                                        "friction_coefficient": friction, "mass_matrix": variant,
                                        "initial_gap": gap},
                          output=["kinetic_energy", "strain_energy", "normal_force",
                                  "top_reaction_y", "top_velocity", "top_position",
                                  "max_penetration"])
    assert np.all(r["kinetic_energy"] <= 1e-12 * r["strain_energy"])
    assert r["strain_energy"][0] > 0 and r["top_position"][0] < -gap
    assert np.all(np.abs(r["max_penetration"]) <= 1e-12)
    np.testing.assert_allclose(r["normal_force"], 15000.0, rtol=1e-6)
    np.testing.assert_allclose(r["top_reaction_y"], -15000.0, rtol=1e-6)
    np.testing.assert_allclose(r["top_position"], r["top_position"][0], rtol=1e-9)


@pytest.mark.parametrize("force", [0.0, -100.0])
def test_static_initial_state_needs_a_pressing_force(instance, vr, force):
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    instance.setInteger([vr["initial_state"], vr["top_control"]], [1, 1])
    instance.setReal([vr["top_force"]], [force])
    with pytest.raises(Exception):
        instance.exitInitializationMode()
    assert "needs top_force > 0" in instance.text()


def test_lift_off_and_re_contact(fmu_path):
    """examples/scenes.py: the top force goes 15 -> -5 -> 15 kN/m (ramped): the contact opens
    (measured from 7 ms) and closes again by the end."""
    import scenes
    r = scenes.lift_off(fmu_path)
    open_steps = r["active_contact_nodes"] == 0
    assert open_steps.any() and not open_steps[0] and r["active_contact_nodes"][-1] > 0
    # normal_force is the step's average: zero once the contact was open the whole step
    assert np.all(r["normal_force"][1:][open_steps[1:] & open_steps[:-1]] == 0)


def test_reversal_turns_the_friction_force(fmu_path):
    """Foundation velocity 0.5 -> -0.5 m/s at 10 ms (F = 0.3, static preload, damped): the
    friction force is +F N before and -F N after (measured 3550 and -3594 N/m)."""
    import scenes
    r = scenes.reversal(fmu_path)
    before, after = r["time"] < 0.0095, r["time"] > 0.012
    ratio = r["friction_force"] / r["normal_force"]
    assert np.mean(ratio[before & (r["time"] > 0.001)]) == pytest.approx(0.3, rel=0.05)
    assert np.mean(ratio[after]) == pytest.approx(-0.3, rel=0.05)
