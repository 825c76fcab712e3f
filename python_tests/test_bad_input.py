"""Bad input never crashes the host: each bad call returns
fmi2Error (a step that cannot be completed too: test_step_failures.py), logs a message naming the
function and the cause, and leaves the instance usable."""
import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2LastSuccessfulTime, fmi2Terminated

from conftest import Instance, not_through_remoting

ERROR, DISCARD = 3, 2
REAL_SETTABLE = ["width", "height", "density", "lambda", "mu", "friction_coefficient",
                 "internal_step", "contact_tolerance", "initial_gap", "foundation_velocity",
                 "top_displacement"]


def expect_error(inst, call, *words, status=ERROR):
    before = len(inst.messages)
    with pytest.raises(FMICallException) as failure:
        call()
    assert failure.value.status == status
    new = [m for m in inst.messages[before:] if m[0] == status]
    assert new, "no log message for a failed call"
    for word in words:
        assert any(word in m[2] for m in new), f"'{word}' not in {new}"


def initialize(inst):
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.exitInitializationMode()


def step_and_read(inst, vr, t=0.0):
    inst.doStep(t, 1e-4)
    return inst.getReal([vr["energy"]])[0]


@pytest.mark.parametrize("name", REAL_SETTABLE)
@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_values_are_refused_and_named(instance, vr, name, value):
    instance.setupExperiment(startTime=0)
    expect_error(instance, lambda: instance.setReal([vr[name]], [value]), "fmi2SetReal", name,
                 "finite")
    instance.enterInitializationMode()
    expect_error(instance, lambda: instance.setReal([vr[name]], [value]), name)
    instance.exitInitializationMode()  # the refused value changed nothing
    if name in ("foundation_velocity", "top_displacement", "friction_coefficient"):
        expect_error(instance, lambda: instance.setReal([vr[name]], [value]), name)
    assert np.isfinite(step_and_read(instance, vr))


@pytest.mark.parametrize("name,value,words", [
    ("density", -1000.0, ["density", "range"]),
    ("density", 0.0, ["density"]),
    ("internal_step", -4e-6, ["internal_step"]),
    ("internal_step", 0.0, ["internal_step"]),
    ("mu", -1.0, ["mu"]),
    ("width", -0.1, ["width"]),
    ("contact_tolerance", 2.0, ["contact_tolerance"]),
    ("initial_gap", -1e-3, ["initial_gap"]),
    ("friction_coefficient", -0.5, ["friction_coefficient"]),
])
def test_out_of_range_reals_are_refused(instance, vr, name, value, words):
    expect_error(instance, lambda: instance.setReal([vr[name]], [value]), *words)
    initialize(instance)
    assert np.isfinite(step_and_read(instance, vr))


@pytest.mark.parametrize("name,value", [("nx", 0), ("ny", -3), ("nx", 10**6), ("mass_matrix", 5),
                                        ("mass_matrix", -1)])
def test_out_of_range_integers_are_refused(instance, vr, name, value):
    expect_error(instance, lambda: instance.setInteger([vr[name]], [value]), "fmi2SetInteger", name)
    initialize(instance)
    assert np.isfinite(step_and_read(instance, vr))


def test_inconsistent_parameters_fail_initialization_and_can_be_fixed(instance, vr):
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    instance.setInteger([vr["ny"]], [1])  # in range, but M_r needs ny >= 2
    expect_error(instance, instance.exitInitializationMode, "fmi2ExitInitializationMode", "ny")
    instance.setInteger([vr["ny"]], [10])
    instance.exitInitializationMode()
    assert np.isfinite(step_and_read(instance, vr))


def test_settings_that_cannot_take_effect_together_are_an_error_naming_both(instance, vr):
    """initial_state = static starts at rest: an initial velocity would be dropped silently."""
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    instance.setInteger([vr["initial_state"]], [1])
    instance.setReal([vr["initial_velocity_y"]], [0.5])
    expect_error(instance, instance.exitInitializationMode, "initial_state", "initial_velocity_y",
                 "initial_velocity_x")
    instance.setReal([vr["initial_velocity_y"]], [0.0])
    instance.exitInitializationMode()
    assert np.isfinite(step_and_read(instance, vr))


def test_fixed_parameters_cannot_change_after_initialization(instance, vr):
    initialize(instance)
    for name in ["density", "width", "internal_step", "contact_tolerance"]:
        expect_error(instance, lambda: instance.setReal([vr[name]], [1.0]), name, "fixed")
    expect_error(instance, lambda: instance.setInteger([vr["nx"]], [10]), "nx", "fixed")
    instance.setReal([vr["friction_coefficient"]], [0.5])  # tunable
    instance.setReal([vr["foundation_velocity"]], [10.0])  # input
    assert np.isfinite(step_and_read(instance, vr))


def test_outputs_cannot_be_set(instance, vr):
    initialize(instance)
    expect_error(instance, lambda: instance.setReal([vr["energy"]], [1.0]), "energy", "output")


@pytest.mark.parametrize("call", ["getReal", "setReal", "getInteger", "setInteger"])
def test_unknown_value_references_are_refused(instance, vr, call):
    initialize(instance)
    fn = getattr(instance, call)
    args = ([987654],) if call.startswith("get") else ([987654], [1])
    expect_error(instance, lambda: fn(*args), "value reference 987654")
    assert np.isfinite(step_and_read(instance, vr))


@not_through_remoting("server builds a std::string from each refused fmi2GetString's null "
                      "value and dies, and the client waits for it forever")
def test_type_mismatch_is_refused(instance, vr):
    initialize(instance)
    expect_error(instance, lambda: instance.getReal([vr["nx"]]), "nx", "Real")
    expect_error(instance, lambda: instance.getInteger([vr["energy"]]), "energy", "Integer")
    expect_error(instance, lambda: instance.getBoolean([vr["energy"]]), "Boolean")
    expect_error(instance, lambda: instance.getString([vr["energy"]]), "String")


def test_calls_out_of_order_are_refused(instance, vr):
    expect_error(instance, lambda: instance.doStep(0.0, 1e-4), "fmi2DoStep", "Instantiated")
    expect_error(instance, instance.exitInitializationMode, "fmi2ExitInitializationMode")
    expect_error(instance, lambda: instance.getReal([vr["energy"]]), "fmi2GetReal")
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    expect_error(instance, lambda: instance.setupExperiment(startTime=0), "fmi2SetupExperiment")
    instance.exitInitializationMode()
    expect_error(instance, instance.enterInitializationMode, "fmi2EnterInitializationMode")
    assert np.isfinite(step_and_read(instance, vr))
    instance.terminate()
    expect_error(instance, lambda: instance.doStep(1e-4, 1e-4), "fmi2DoStep", "Terminated")
    instance.reset()  # back to a fresh instance
    initialize(instance)
    assert np.isfinite(step_and_read(instance, vr))


@pytest.mark.parametrize("t,h,words", [(0.0, -1e-4, ["communicationStepSize"]),
                                       (0.0, 0.0, ["communicationStepSize"]),
                                       (0.0, math.nan, ["communicationStepSize"]),
                                       (0.5, 1e-4, ["currentCommunicationPoint"]),
                                       (math.nan, 1e-4, ["currentCommunicationPoint"])])
def test_bad_steps_are_refused(instance, vr, t, h, words):
    initialize(instance)
    expect_error(instance, lambda: instance.doStep(t, h), "fmi2DoStep", *words)
    assert np.isfinite(step_and_read(instance, vr))


@not_through_remoting("returns fmi2Error without the FMU's log message (observed)")
def test_unsupported_capabilities_answer_with_an_error(instance):
    initialize(instance)
    expect_error(instance, lambda: instance.getDirectionalDerivative([100], [20], [1.0]),
                 "fmi2GetDirectionalDerivative", "not supported")


@not_through_remoting("server answers fmi2SetDebugLogging with fmi2Error itself")
def test_unknown_log_category_is_refused(instance):
    expect_error(instance, lambda: instance.setDebugLogging(True, ["noSuchCategory"]),
                 "noSuchCategory")
    instance.setDebugLogging(True, ["logEvents"])
    initialize(instance)
    assert any("initialized" in m[2] for m in instance.messages)


def test_coarse_mesh_rule_for_the_redistributed_mass(model_description, unzipped, vr):
    """The rule the message states: M_r fails for ny = 3 and nx >= 3 only (the least change
    failed for ny = 2 and nx >= 2 and ny = 4 and nx >= 7 too; the least relative change carries
    those); the consistent mass always works."""
    inst = Instance(model_description, unzipped, "coarse")
    try:
        for ny in (2, 3, 4, 5):
            for nx in (1, 2, 3, 6, 7, 12):
                for variant in (1, 3):
                    inst.reset()
                    inst.setupExperiment(startTime=0)
                    inst.enterInitializationMode()
                    inst.setInteger([vr["nx"], vr["ny"], vr["mass_matrix"]], [nx, ny, variant])
                    fails = variant == 1 and ny == 3 and nx >= 3
                    if fails:
                        expect_error(inst, inst.exitInitializationMode,
                                     f"nx = {nx}, ny = {ny}", "ny = 3 fails for nx >= 3",
                                     "Use ny = 2, 4 or more, or mass_matrix = 0 or 3")
                    else:
                        inst.exitInitializationMode()
    finally:
        inst.close()


def limited_parameters(model_description):
    """(name, type, min, max) of every parameter with a limit in the modelDescription."""
    out = []
    for v in model_description.modelVariables:
        if v.causality != "parameter" or v.type not in ("Real", "Integer", "Enumeration"):
            continue
        low = None if v.min is None else float(v.min)
        high = None if v.max is None else float(v.max)
        if low is not None or high is not None:
            out.append((v.name, v.type, low, high))
    return out


def test_ranges_in_the_model_description_are_what_the_fmu_refuses(model_description, unzipped,
                                                                   vr):
    """Every written limit is the FMU's own. min and max are accepted (and
    initialize alone), the next representable value beyond each is refused, naming it. Where
    a value must be > 0, min is the smallest meaningful positive value, not 0."""
    checked = 0
    for name, kind, low, high in limited_parameters(model_description):
        for limit, outward in ((low, -math.inf), (high, math.inf)):
            if limit is None or math.isinf(limit):
                continue
            inst = Instance(model_description, unzipped, "ranges")
            try:
                inst.setupExperiment(startTime=0)
                inst.enterInitializationMode()
                if kind == "Real":
                    set_value = lambda x: inst.setReal([vr[name]], [x])  # noqa: E731
                    beyond = math.nextafter(limit, outward)
                else:
                    set_value = lambda x: inst.setInteger([vr[name]], [int(x)])  # noqa: E731
                    beyond = limit + (1 if outward > 0 else -1)
                    if abs(beyond) >= 2**31:
                        continue
                expect_error(inst, lambda: set_value(beyond), name)
                set_value(limit)
                if name in ("nx", "ny") and limit > 1000:
                    continue  # a 4096-cell side initializes, but slowly: the setter is the check
                if name == "modes" and limit > 1000:
                    continue  # needs a body of 2000 finite modes (nx = ny = 32): the setter is the check
                if name == "ny" and limit == 1:
                    inst.setInteger([vr["mass_matrix"]], [0])  # M_r needs ny >= 2 (tested above)
                inst.exitInitializationMode()
                checked += 1
            finally:
                inst.close()
    assert checked >= 20
    written = {name: low for name, _, low, _ in limited_parameters(model_description)}
    for name in ("width", "height", "density", "mu", "internal_step", "min_internal_step",
                 "contact_tolerance", "top_mass", "field_output_interval"):
        assert written[name] > 0, name
