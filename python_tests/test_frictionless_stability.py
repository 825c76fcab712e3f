"""Without friction: where the paper's midpoint contact gains energy, the energy
comes in as work of the normal contact forces, and redistributed_implicit_contact (mass_matrix
= 4: M_r, contact at the end of the step) cannot gain any."""
import fmpy
from fmpy.fmi1 import FMICallException
import numpy as np
import pytest

from conftest import Instance

MU = 150e6
OUT = ["energy", "normal_contact_work", "clamp_work", "kinetic_energy", "max_penetration"]


def frictionless(fmu_path, variant, ratio, dt, stop):
    return fmpy.simulate_fmu(fmu_path, stop_time=stop, output_interval=dt * round(1e-4 / dt),
                             start_values={"friction_coefficient": 0.0, "lambda": ratio * MU,
                                           "mass_matrix": variant, "internal_step": dt,
                                           # these tests measure the growth: no guard
                                           "max_energy_ratio": 0.0},
                             output=OUT)


@pytest.mark.parametrize("dt", [4e-6, 8e-6])
def test_the_paper_scheme_gains_energy_through_the_normal_contact_work(fmu_path, dt):
    """lambda/mu = 10, 0.02 s: all of E - E(0) is the work of the normal contact forces.
    At dt = 4e-6 the growth is in the extrapolated integer-step values of the massless normal
    dofs (the kinetic energy stays near E(0)); at dt = 8e-6 the motion itself grows."""
    r = frictionless(fmu_path, 1, 10, dt, 0.02)
    e, kinetic = r["energy"], r["kinetic_energy"]
    assert np.all(r["clamp_work"] == 0)
    np.testing.assert_allclose(e - e[0], r["normal_contact_work"], rtol=0, atol=1e-9 * e.max())
    assert e.max() > 20 * e[0]
    if dt == 4e-6:
        assert kinetic.max() < 2 * e[0]
    else:
        assert kinetic.max() > 1e6 * e[0]
    # It enters where the midpoint leaves the integer steps penetrating: lambda_N acts on
    # u^{k+1/2} = gap while u_N^k > gap, so lambda_N (u_N^{k+1} - u_N^k) > 0.
    assert r["max_penetration"].max() > 1e-5


@pytest.mark.parametrize("ratio", [2, 4, 10, 50])
@pytest.mark.parametrize("dt", [1e-6, 4e-6, 1.6e-5])
def test_implicit_contact_with_redistributed_mass_never_gains_energy(fmu_path, ratio, dt):
    """F = 0, top held, 0.05 s: E never exceeds E(0) by more than 1 %, and never regains
    energy once lost, beyond round-off (1e-9 E(0): the balance's tolerance); the normal
    contact work, a sum of terms lambda_N (gap - u_N^k) <= 0, only decreases."""
    r = frictionless(fmu_path, 4, ratio, dt, 0.05)
    e, w = r["energy"], r["normal_contact_work"]
    assert abs(r["time"][-1] - 0.05) < 1e-9 and np.isfinite(e).all()
    assert e.max() <= 1.01 * e[0]
    assert np.all(e - np.minimum.accumulate(e) <= 1e-9 * e[0])
    assert np.all(np.diff(w) <= 1e-12 * e[0])
    assert r["max_penetration"].max() <= 1e-15  # contact holds at the integer steps


def stress_scene(model_description, unzipped, vr, variant, stop=0.026, h=2.12e-5, guard=True):
    """The issue's random stress scene: 39 x 14 cells, initial gap, top held at -1.07e-5 m
    for 0.01 s, then ramped with input derivatives to +2.7e-5 m (tension) over 0.01 s.
    guard=False turns the blow-up guard off (max_energy_ratio = 0)."""
    inst = Instance(model_description, unzipped, "stress")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setInteger([vr["nx"], vr["ny"], vr["mass_matrix"]], [39, 14, variant])
        names = ["width", "height", "density", "mu", "lambda", "initial_gap",
                 "friction_coefficient", "internal_step", "top_displacement"]
        inst.setReal([vr[n] for n in names],
                     [0.0534, 0.0297, 200, 6.8e8, 2.79e9, 2.57e-6, 0.0, 2.12e-6, -1.07e-5])
        if not guard:
            inst.setReal([vr["max_energy_ratio"]], [0.0])
        inst.exitInitializationMode()
        refs = [vr[n] for n in ("energy", "clamp_work", "normal_contact_work")]
        e0 = inst.getReal(refs)[0]
        rows = []
        for k in range(round(stop / h)):
            t = k * h
            if abs(t - 0.01) < h / 2:
                inst.setRealInputDerivatives([vr["top_displacement"]], [1], [3.77e-5 / 0.01])
            if abs(t - 0.02) < h / 2:
                inst.setReal([vr["top_displacement"]], [2.7e-5])  # held from here on
            inst.doStep(t, h)
            rows.append(inst.getReal(refs))
        return e0, np.array(rows)
    finally:
        inst.close()


def test_stress_scene_stays_bounded_with_the_stable_scheme(model_description, unzipped, vr):
    e0, rows = stress_scene(model_description, unzipped, vr, 4)
    energy, clamp, normal = rows.T
    assert np.isfinite(rows).all()
    # Everything that entered came through the clamp; contact only took energy out.
    assert np.all(normal <= 1e-10 * e0) and np.all(np.diff(normal) <= 1e-10 * e0)
    assert np.all(energy <= e0 + clamp + 1e-9 * np.abs(energy).max())
    assert energy.max() < 10 * (e0 + np.abs(clamp).max())


def test_stress_scene_blows_up_with_the_paper_scheme(model_description, unzipped, vr):
    """The contrast: the same scene with redistributed_normal gains orders of magnitude."""
    e0, rows = stress_scene(model_description, unzipped, vr, 1, stop=0.01, guard=False)
    assert rows[-1, 0] > 1e3 * e0 and rows[-1, 2] > 0.99 * (rows[-1, 0] - e0)


def test_the_blow_up_guard_ends_it_with_an_error_naming_the_cause(model_description, unzipped,
                                                                   vr):
    """With the guard on (the default max_energy_ratio = 1e6), the same growth ends in
    fmi2Error once E passes 1e6 x (E(0) + the work put in), the state restored to the step's
    start, and the message names the time, E, the works and the likely cause; the outputs
    stayed finite and below the limit up to there."""
    inst = Instance(model_description, unzipped, "guard")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.setInteger([vr["nx"], vr["ny"], vr["mass_matrix"]], [39, 14, 1])
        names = ["width", "height", "density", "mu", "lambda", "initial_gap",
                 "friction_coefficient", "internal_step", "top_displacement"]
        inst.setReal([vr[n] for n in names],
                     [0.0534, 0.0297, 200, 6.8e8, 2.79e9, 2.57e-6, 0.0, 2.12e-6, -1.07e-5])
        inst.exitInitializationMode()
        e0 = inst.getReal([vr["energy"]])[0]
        h, t, last = 2.12e-5, 0.0, None
        with pytest.raises(FMICallException) as failure:
            for _ in range(round(0.01 / h)):
                inst.doStep(t, h)
                last = inst.getReal([vr["energy"]])[0]
                t += h
        assert failure.value.status == 3  # fmi2Error
        assert last is not None and np.isfinite(last) and last <= 1e6 * e0
        assert inst.getReal([vr["energy"]])[0] == last  # restored to the step's start
        text = inst.text()
        for words in ("fmi2DoStep", "exceeds max_energy_ratio", "clamp_work = 0",
                      "normal_contact_work = ", "grows without bound",
                      "likely cause: the contact created", "midpoint contact of mass_matrix = 1",
                      "mass_matrix = 4"):
            assert words in text, words
    finally:
        inst.close()
