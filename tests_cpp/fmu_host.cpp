// A minimal FMI 2.0 host, run under valgrind by python_tests/test_valgrind.py: it loads
// ContactBody.so, simulates, saves, serializes and restores a state, makes a bad call, and
// frees everything. Exit status 0 when every call returned what it should.
#include <cmath>
#include <cstdio>
#include <vector>

#include "fmi_host.hpp"

namespace {

using host::logger;

int failures = 0;
void expect(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: fmu_host ContactBody.so GUID\n");
        return 2;
    }
    void* lib = host::load_library(argv[1]);
    if (!lib) return 2;
#define LOAD(f)                                                  \
    auto* f = reinterpret_cast<f##TYPE*>(host::symbol(lib, #f)); \
    expect(f != nullptr, #f)
    LOAD(fmi2Instantiate);
    LOAD(fmi2SetupExperiment);
    LOAD(fmi2EnterInitializationMode);
    LOAD(fmi2ExitInitializationMode);
    LOAD(fmi2DoStep);
    LOAD(fmi2GetReal);
    LOAD(fmi2SetReal);
    LOAD(fmi2GetFMUstate);
    LOAD(fmi2SetFMUstate);
    LOAD(fmi2FreeFMUstate);
    LOAD(fmi2SerializedFMUstateSize);
    LOAD(fmi2SerializeFMUstate);
    LOAD(fmi2DeSerializeFMUstate);
    LOAD(fmi2Terminate);
    LOAD(fmi2FreeInstance);
#undef LOAD
    if (failures) return 1;

    fmi2CallbackFunctions callbacks = {logger, nullptr, nullptr, nullptr, nullptr};
    fmi2Component c =
        fmi2Instantiate("host", fmi2CoSimulation, argv[2], "", &callbacks, fmi2False, fmi2False);
    expect(c != nullptr, "instantiate");
    if (!c) return 1;
    expect(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK, "setup");
    expect(fmi2EnterInitializationMode(c) == fmi2OK, "enter");
    expect(fmi2ExitInitializationMode(c) == fmi2OK, "exit");

    const fmi2ValueReference energy = 100, nan_target = 5;
    double t = 0, e = 0;
    fmi2FMUstate saved = nullptr;
    for (int k = 0; k < 40; ++k, t += 1e-4) {
        expect(fmi2DoStep(c, t, 1e-4, fmi2True) == fmi2OK, "step");
        if (k == 20) expect(fmi2GetFMUstate(c, &saved) == fmi2OK, "get state");
    }
    expect(fmi2GetReal(c, &energy, 1, &e) == fmi2OK && std::isfinite(e), "energy");

    size_t size = 0;
    expect(fmi2SerializedFMUstateSize(c, saved, &size) == fmi2OK, "state size");
    std::vector<fmi2Byte> bytes(size);
    expect(fmi2SerializeFMUstate(c, saved, bytes.data(), size) == fmi2OK, "serialize");
    fmi2FMUstate restored = nullptr;
    expect(fmi2DeSerializeFMUstate(c, bytes.data(), size, &restored) == fmi2OK, "deserialize");
    expect(fmi2DeSerializeFMUstate(c, bytes.data(), size / 2, &restored) == fmi2Error, "truncated");
    expect(fmi2SetFMUstate(c, restored) == fmi2OK, "set state");
    t = 21e-4;
    for (int k = 21; k < 40; ++k, t += 1e-4) expect(fmi2DoStep(c, t, 1e-4, fmi2True) == fmi2OK, "replay");
    double e2 = 0;
    expect(fmi2GetReal(c, &energy, 1, &e2) == fmi2OK && e2 == e, "replay is identical");

    const double bad = NAN;
    expect(fmi2SetReal(c, &nan_target, 1, &bad) == fmi2Error, "NaN refused");
    expect(fmi2FreeFMUstate(c, &saved) == fmi2OK, "free state");
    // `restored` is left for fmi2FreeInstance to free.
    expect(fmi2Terminate(c) == fmi2OK, "terminate");
    fmi2FreeInstance(c);
    dlclose(lib);
    return failures ? 1 : 0;
}
