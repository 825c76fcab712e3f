"""Friction that depends on the slip rate, F(v) = F_d + (F_s - F_d)
exp(-|v| / v_s) + c_v |v| (F_d = friction_coefficient, F_s = static_friction_ratio x F_d,
v_s = stribeck_velocity, c_v = viscous_friction), with v the scheme's discrete slip rate taken
implicitly in the step."""
import fmpy
import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from conftest import FMU, PLATFORM
from test_energy_balance import check_balance, run_balance

FMU3 = FMU.with_name("ContactBody_fmi3.fmu")
LAW = {"friction_coefficient": 0.2, "static_friction_ratio": 1.5, "stribeck_velocity": 1.0,
       "viscous_friction": 0.002}


def law(v, friction_coefficient, static_friction_ratio, stribeck_velocity, viscous_friction):
    v = np.abs(v)
    return (friction_coefficient + (static_friction_ratio - 1) * friction_coefficient
            * np.exp(-v / stribeck_velocity) + viscous_friction * v)


@pytest.mark.skipif(PLATFORM != "linux64", reason="reads the FMI 3.0 FMU's edge arrays")
@pytest.mark.parametrize("V", [2.0, 5.0, 20.0])
def test_every_slipping_node_feels_the_law_at_its_own_slip_rate(V):
    """One output per substep (output_interval = internal_step), so that the step-averaged
    pressure and friction density are the substep's, with the same substep's slip rate: at
    every slipping node and output |T_i| = F(v_i) N_i to 1e-9 of the row's largest N_i (the
    contact solve's tolerance is relative to the largest multiplier), sticking nodes stay inside
    the static bound F(0) = F_s, and where the slip is steady (all nodes slipping within
    0.5 % of one rate) the whole edge's friction_force / normal_force is F at the
    pressure-weighted slip rate to 1e-6."""
    r = fmpy.simulate_fmu(str(FMU3), stop_time=0.03, output_interval=4e-6, start_values={
        **LAW, "damping_stiffness": 4e-6, "foundation_velocity": V, "initial_state": 1})
    p, f, v, state = (r[n] for n in ("edge_pressure", "edge_friction", "edge_slip_velocity",
                                     "edge_state"))
    slipping = (state == 2) & (p > 0)
    assert slipping.sum() > 1000
    scale = np.broadcast_to(p.max(axis=1, keepdims=True), p.shape)[slipping]
    error = np.abs(np.abs(f[slipping]) - law(v[slipping], **LAW) * p[slipping]) / scale
    assert error.max() <= 1e-9, error.max()
    # friction opposes the slip
    assert np.all(np.sign(f[slipping]) == -np.sign(v[slipping]))
    sticking = (state == 1) & (p > 0)
    bound = law(0, **LAW) * p[sticking] + 1e-9 * np.broadcast_to(p.max(axis=1, keepdims=True), p.shape)[sticking]
    assert np.all(np.abs(f[sticking]) <= bound)
    # Steady: every node slips, at slip rates within 0.5 % of each other.
    spread = v.max(axis=1) - v.min(axis=1)
    full = (state == 2).all(axis=1) & (r["normal_force"] > 0) & (spread <= 5e-3 * V)
    assert full.sum() >= 500, full.sum()
    share = np.diff(r["edge_x"][0])
    share = np.concatenate([[share[0] / 2], (share[:-1] + share[1:]) / 2, [share[-1] / 2]])
    weights = p[full] * share
    v_mean = (weights * v[full]).sum(axis=1) / weights.sum(axis=1)
    np.testing.assert_allclose(np.abs(r["friction_force"][full] / r["normal_force"][full]),
                               law(v_mean, **LAW), rtol=1e-6)


@pytest.mark.parametrize("variant", [0, 1, 2, 3, 4])
@pytest.mark.parametrize("terms", [{"static_friction_ratio": 1.5, "stribeck_velocity": 2.0},
                                   {"viscous_friction": 0.05},
                                   {"static_friction_ratio": 2.0, "stribeck_velocity": 0.5,
                                    "viscous_friction": 0.01}],
                         ids=["stribeck", "viscous", "both"])
def test_energy_balance_closes_with_the_slip_rate_law(model_description, unzipped, vr, variant,
                                                      terms):
    """The foundation's velocity swings through zero (20 cos(900 t)): the law is used from
    the static peak to 20 m/s. E - E(0) = the works to 1e-9, friction dissipates."""
    start, rows = run_balance(model_description, unzipped, vr, variant, 0.3, 0, 4e-6, "held",
                              **terms)
    check_balance(start, rows, variant, "held", 0.3, 4e-6)


def test_the_defaults_keep_the_constant_law(model_description, unzipped, vr):
    """stribeck_velocity = viscous_friction = 0 is today's law: setting them to 0 changes no
    bit, a Stribeck velocity with static_friction_ratio = 1 neither (its drop is 0), and a
    small viscous term does change the outputs."""
    outputs = ["energy", "friction_force", "friction_dissipation"]
    run = lambda **s: fmpy.simulate_fmu(str(FMU), stop_time=2e-3, output_interval=1e-4,
                                        output=outputs, start_values={
                                            "friction_coefficient": 0.3, "damping_stiffness": 4e-6,
                                            **s})
    base = run()
    for same in ({"stribeck_velocity": 0.0, "viscous_friction": 0.0}, {"stribeck_velocity": 1.0}):
        other = run(**same)
        assert all(base[n].tobytes() == other[n].tobytes() for n in outputs), same
    assert base["friction_force"].tobytes() != run(viscous_friction=1e-3)["friction_force"].tobytes()


@pytest.mark.parametrize("name,value", [("stribeck_velocity", -1.0), ("viscous_friction", 101.0),
                                        ("stribeck_velocity", float("inf"))])
def test_bad_law_parameters_are_refused_by_name(instance, vr, name, value):
    with pytest.raises(FMICallException):
        instance.setReal([vr[name]], [value])
    assert name in instance.text()
