"""test_fuzz_fmi.py's property for the FMI 3.0 layer. Random sequences of FMI 3.0
calls (typed setters with bad values and wrong types, array reads with wrong sizes,
Configuration Mode, steps, states): every call returns a status (an exception here would be
a crash of the host), every failure is logged, and a failed call changes nothing: replaying
only the calls that succeeded on a fresh instance gives the same outputs."""
import math
import os

import fmpy
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import fmi3FMUState
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import FMU, PLATFORM, SANITIZED, extract_for
from test_fmi3 import Instance3
from test_fuzz_fmi import Driver, run_sequence, same

pytestmark = pytest.mark.skipif(PLATFORM != "linux64", reason="the FMI 3.0 FMU is tested on linux64")

# The sanitizer job runs a third of them: each call is several times slower there.
EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES_FMI3", "200" if SANITIZED else "600"))
FMU3 = FMU.with_name("ContactBody_fmi3.fmu")
NASTY_REALS = [math.nan, math.inf, -1e308, -1.0, 0.0, 5e-324, 1e-300, 2.5e-5, 0.3, 20.0]
NASTY_UINTS = [0, 1, 3, 4, 5, 6, 21, 4097, 2**31, 2**64 - 1]
NASTY_INTS = [0, 1, 2, 4, 5, -1, 2**40, -2**63]
NASTY_STEPS = [1e-4, 7e-5, 1e-3, 0.0, -1e-4, math.nan, math.inf, 1e300]


@pytest.fixture(scope="module")
def md3():
    return fmpy.read_model_description(str(FMU3))


@pytest.fixture(scope="module")
def unzipped3():
    return extract_for("linux64", FMU3)


def calls(md):
    by_type = lambda *types: [v.valueReference for v in md.modelVariables if v.type in types]
    floats, uints, enums = by_type("Float64"), by_type("UInt64"), by_type("Enumeration")
    vr_float = st.sampled_from(floats + [999, uints[0], enums[0]])
    real = st.one_of(st.sampled_from(NASTY_REALS), st.floats(allow_nan=True, allow_infinity=True))
    step = st.tuples(st.just("doStep"), st.sampled_from(["now"] * 6 + ["late", "early"]),
                     st.sampled_from(NASTY_STEPS[:3] * 3 + NASTY_STEPS))
    return st.one_of(
        st.tuples(st.just("setFloat64"), vr_float, real),
        st.tuples(st.just("setUInt64"), st.sampled_from(uints + [floats[0]]),
                  st.sampled_from(NASTY_UINTS)),
        st.tuples(st.just("setInt64"), st.sampled_from(enums + [uints[0]]),
                  st.sampled_from(NASTY_INTS)),
        st.tuples(st.just("setInt32"), st.sampled_from(uints + enums), st.sampled_from([1, 4])),
        st.tuples(st.just("getFloat64"), vr_float, st.sampled_from([1, 5, 0, 21, 6])),
        st.tuples(st.just("getInt64"), st.sampled_from(enums), st.sampled_from([1, 5, 4])),
        st.tuples(st.just("getUInt64"), st.sampled_from(uints)),
        step, step, step,
        st.tuples(st.sampled_from(["enterConfigurationMode", "exitConfigurationMode",
                                   "enterInitializationMode", "exitInitializationMode",
                                   "terminate", "reset", "enterEventMode", "getFMUstate",
                                   "setFMUstate", "serializeRoundTrip", "badState"])),
    )


class Driver3(Driver):
    """test_fuzz_fmi's driver on an FMI 3.0 instance, with the FMI 3.0 calls."""

    STATE = {"get": "getFMUState", "set": "setFMUState", "serialize": "serializeFMUState",
             "deserialize": "deserializeFMUState"}
    BAD_STATE = fmi3FMUState

    def instantiate(self, md, unzipped, name):
        inst = Instance3(md, unzipped, name)
        inst.setUInt64([3, 4], [4, 4])  # a small mesh keeps the sequences fast
        return inst

    def apply_other(self, call):
        inst, op = self.inst, call[0]
        if op in ("setFloat64", "setUInt64", "setInt64", "setInt32"):
            return getattr(inst, op)([call[1]], [call[2]])
        if op in ("getFloat64", "getInt64"):
            return getattr(inst, op)([call[1]], call[2])
        if op == "getUInt64":
            return inst.getUInt64([call[1]])
        if op == "enterInitializationMode":
            inst.enterInitializationMode(startTime=0.0)
            self.time = 0.0
            return None
        return getattr(inst, op)()

    def outputs(self, md):
        scalars = [v.valueReference for v in md.modelVariables
                   if v.type == "Float64" and v.causality == "output" and not v.dimensions]
        try:
            values = self.inst.getFloat64(scalars)
            nodes = self.inst.getUInt64([31])[0]
            return values + self.inst.getFloat64([131, 134], 2 * nodes)
        except FMICallException as e:
            return ("status", e.status)

    def close(self):
        self.inst.slave.freeInstance()


def test_random_fmi3_call_sequences(md3, unzipped3):
    prelude = st.lists(calls(md3).filter(lambda c: c[0].startswith("set")), max_size=4).map(
        lambda sets: [("enterInitializationMode",)] + sets + [("exitInitializationMode",)])
    configured = st.lists(st.tuples(st.just("setUInt64"), st.sampled_from([3, 4, 31]),
                                    st.sampled_from([2, 3, 4, 5])), max_size=3).map(
        lambda sets: [("enterConfigurationMode",)] + sets + [("exitConfigurationMode",),
                                                             ("enterInitializationMode",),
                                                             ("exitInitializationMode",)])
    sequences = st.tuples(st.one_of(prelude, prelude, configured, st.just([])),
                          st.lists(calls(md3), min_size=2, max_size=20)).map(lambda p: p[0] + p[1])

    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(sequences)
    def check(sequence):
        kept, results, out = run_sequence(md3, unzipped3, sequence, "fuzz", Driver3)
        assert all(r[0] == "ok" or r[1] == 3 for r in results)  # no discard in FMI 3.0 here
        _, _, replay = run_sequence(md3, unzipped3, kept, "replay", Driver3)
        assert same(out, replay), "failed calls must not change the instance"

    check()
