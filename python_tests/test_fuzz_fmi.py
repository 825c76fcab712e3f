"""Random sequences of FMI calls, values, value references and step sizes.
Every call returns a status (an exception here would be a crash of the host), every failure
is logged, and a failed call changes nothing: replaying only the calls that succeeded on a
fresh instance gives the same outputs."""
import ctypes
import math
import os

import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2FMUstate
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import Instance

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "4000"))

NASTY_REALS = [math.nan, math.inf, -math.inf, 1e308, -1e308, -1.0, 0.0, 5e-324, -5e-324,
               1e-300, 2.5e-5, 0.3, 20.0]
NASTY_INTS = [0, -1, 1, 3, 4, 7, 2**31 - 1, -2**31]
NASTY_STEPS = [1e-4, 7e-5, 3e-6, 1e-3, 0.0, -1e-4, math.nan, math.inf, 1e300, 5e-324]


def value_refs(md, types):
    return [v.valueReference for v in md.modelVariables if v.type in types]


def setters(md):
    reals = value_refs(md, ("Real",))
    ints = value_refs(md, ("Integer", "Enumeration"))
    vr_real = st.sampled_from(reals + [0, 999, 2**32 - 1, ints[0]])
    vr_int = st.sampled_from(ints + [0, 999, reals[0]])
    real = st.one_of(st.sampled_from(NASTY_REALS), st.floats(allow_nan=True, allow_infinity=True))
    return st.one_of(
        st.tuples(st.just("setReal"), vr_real, real),
        st.tuples(st.just("setInteger"), vr_int, st.one_of(st.sampled_from(NASTY_INTS),
                                                            st.integers(-2**31, 2**31 - 1))))


def calls(md):
    reals = value_refs(md, ("Real",))
    ints = value_refs(md, ("Integer", "Enumeration"))
    vr_real = st.sampled_from(reals + [0, 999, 2**32 - 1, ints[0]])
    vr_int = st.sampled_from(ints + [0, 999, reals[0]])
    step = st.tuples(st.just("doStep"), st.sampled_from(["now"] * 6 + ["late", "early"]),
                     st.sampled_from(NASTY_STEPS[:4] * 3 + NASTY_STEPS))
    return st.one_of(
        setters(md), step, step, step,
        st.tuples(st.just("getReal"), vr_real),
        st.tuples(st.just("getInteger"), vr_int),
        st.tuples(st.just("derivative"), st.sampled_from([20, 21, 5, 999]),
                  st.sampled_from([1, 0, 2]), st.sampled_from(NASTY_REALS)),
        st.tuples(st.sampled_from(["setupExperiment", "enterInitializationMode",
                                   "exitInitializationMode", "terminate", "reset",
                                   "getFMUstate", "setFMUstate", "serializeRoundTrip",
                                   "badState", "getRealStatus", "getBooleanStatus"])),
    )


class Driver:
    """Runs calls on an instance; returns (status, value) and keeps the successful calls.
    The FMI 3.0 fuzz (test_fuzz_fmi3.py) subclasses it with its own instance, calls and
    names of the state functions."""

    STATE = {"get": "getFMUstate", "set": "setFMUstate", "serialize": "serializeFMUstate",
             "deserialize": "deSerializeFMUstate"}
    BAD_STATE = fmi2FMUstate

    def __init__(self, md, unzipped, name):
        self.inst = self.instantiate(md, unzipped, name)
        self.time = 0.0
        self.states = []

    def instantiate(self, md, unzipped, name):
        inst = Instance(md, unzipped, name)
        inst.setInteger([3, 4], [4, 4])  # a small mesh keeps thousands of sequences fast
        return inst

    def apply(self, call):
        """The calls both standards share; the rest goes to apply_other."""
        inst, op = self.inst, call[0]
        state = {k: getattr(inst, v) for k, v in self.STATE.items()}
        if op == "doStep":
            t = {"now": self.time, "late": self.time + 1.0, "early": self.time - 1e-3}[call[1]]
            inst.doStep(t, call[2])
            self.time = t + call[2]
            return None
        if op == "getFMUstate":
            self.states.append((state["get"](), self.time))
            return None
        if op == "setFMUstate":
            if not self.states:
                raise LookupError  # nothing to restore: not a call
            saved, t = self.states[-1]
            state["set"](saved)
            self.time = t
            return None
        if op == "serializeRoundTrip":
            if not self.states:
                raise LookupError
            saved, t = self.states[-1]
            self.states.append((state["deserialize"](state["serialize"](saved)), t))
            return None
        if op == "badState":
            return state["set"](self.BAD_STATE(0xDEAD))
        if op == "reset":
            inst.reset()
            self.time = 0.0
            return None
        return self.apply_other(call)

    def apply_other(self, call):
        inst, op = self.inst, call[0]
        if op == "setReal":
            return inst.setReal([call[1]], [call[2]])
        if op == "setInteger":
            return inst.setInteger([call[1]], [call[2]])
        if op == "getReal":
            return inst.getReal([call[1]])[0]
        if op == "getInteger":
            return inst.getInteger([call[1]])[0]
        if op == "derivative":
            return inst.setRealInputDerivatives([call[1]], [call[2]], [call[3]])
        if op == "setupExperiment":
            inst.setupExperiment(startTime=0.0)
            self.time = 0.0
            return None
        if op == "getRealStatus":
            return inst.getRealStatus(2)
        if op == "getBooleanStatus":
            return inst.getBooleanStatus(3)
        return getattr(inst, op)()

    def outputs(self, md):
        try:
            return self.inst.getReal([v.valueReference for v in md.modelVariables
                                      if v.type == "Real"])
        except FMICallException as e:
            return ("status", e.status)

    def close(self):
        self.inst.close()


def run_sequence(md, unzipped, sequence, name, driver=Driver):
    d = driver(md, unzipped, name)
    kept, results = [], []
    for call in sequence:
        before = len(d.inst.messages)
        saved_time = d.time
        try:
            value = d.apply(call)
            kept.append(call)
            results.append(("ok", value))
        except LookupError:
            continue
        except FMICallException as e:
            assert e.status in (2, 3), f"{call}: status {e.status}"
            assert len(d.inst.messages) > before, f"{call} failed without a log message"
            failed_step = call[0] == "doStep" and any(
                "failed, state restored" in m[2] for m in d.inst.messages[before:])
            if e.status == 2 or failed_step:  # a real event: it stays in the replay
                kept.append(call)
            else:
                d.time = saved_time
            results.append(("failed", e.status))
    out = d.outputs(md)
    d.close()
    return kept, results, out


def same(a, b):
    if isinstance(a, tuple) or isinstance(b, tuple):
        return a == b
    return all((x == y) or (math.isnan(x) and math.isnan(y)) for x, y in zip(a, b))


@pytest.fixture(scope="module")
def call_strategy(model_description):
    """Most sequences initialize (with random, often bad, parameter values) and then run."""
    prelude = st.lists(setters(model_description), max_size=4).map(
        lambda sets: [("setupExperiment",), ("enterInitializationMode",)] + sets
        + [("exitInitializationMode",)])
    return st.tuples(st.one_of(prelude, prelude, prelude, st.just([])),
                     st.lists(calls(model_description), max_size=20)).map(lambda p: p[0] + p[1])


def test_random_fmi_call_sequences(model_description, unzipped, call_strategy):
    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(call_strategy)
    def check(sequence):
        kept, _, out = run_sequence(model_description, unzipped, sequence, "fuzz")
        _, _, replay = run_sequence(model_description, unzipped, kept, "replay")
        assert same(out, replay), "failed calls must not change the instance"

    check()
