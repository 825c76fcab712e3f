// A minimal FMI 3.0 host, state_host's counterpart for the FMI 3.0 layer, on any platform
// (python_tests/test_windows.py runs its win64 build under wine): it loads the FMU binary,
// instantiates with the instantiation token, optionally sets nx in Configuration Mode
// (NX, or "-"), initializes, restores the state from STATE_IN (unless "-"), takes STEPS steps
// of H from T0, writes the Float64 values of VR:COUNT pairs (COUNT values each: 1 for a
// scalar, edge_nodes for an array) after each step as hex floats (one line a step) to
// OUTPUTS, and the final state, serialized, to STATE_OUT.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fmi_host.hpp"

extern "C" {
#include "fmi3Functions.h"
}

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fmi3_host: %s failed\n", what);
    std::exit(1);
}

void check(fmi3Status status, const char* what) {
    if (status != fmi3OK) fail(what);
}

void log_message(fmi3InstanceEnvironment, fmi3Status status, fmi3String category, fmi3String message) {
    std::fprintf(stderr, "[fmi3_host %d %s] %s\n", static_cast<int>(status), category, message);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 10) {
        std::fprintf(stderr,
                     "usage: fmi3_host LIBRARY TOKEN NX|- STATE_IN|- T0 STEPS H OUTPUTS "
                     "STATE_OUT VR:COUNT...\n");
        return 2;
    }
    void* library = host::load_library(argv[1]);
    if (!library) fail("loading the library");
#define LOAD(f)                                                      \
    auto* f = reinterpret_cast<f##TYPE*>(host::symbol(library, #f)); \
    if (!f) fail(#f)
    LOAD(fmi3InstantiateCoSimulation);
    LOAD(fmi3EnterConfigurationMode);
    LOAD(fmi3ExitConfigurationMode);
    LOAD(fmi3SetUInt64);
    LOAD(fmi3EnterInitializationMode);
    LOAD(fmi3ExitInitializationMode);
    LOAD(fmi3DoStep);
    LOAD(fmi3GetFloat64);
    LOAD(fmi3GetFMUState);
    LOAD(fmi3SetFMUState);
    LOAD(fmi3FreeFMUState);
    LOAD(fmi3SerializedFMUStateSize);
    LOAD(fmi3SerializeFMUState);
    LOAD(fmi3DeserializeFMUState);
    LOAD(fmi3Terminate);
    LOAD(fmi3FreeInstance);
#undef LOAD
    const double t0 = std::strtod(argv[5], nullptr), h = std::strtod(argv[7], nullptr);
    const int steps = std::atoi(argv[6]);
    std::vector<fmi3ValueReference> vrs;
    size_t count = 0;
    for (int i = 10; i < argc; ++i) {
        const std::string pair = argv[i];
        const size_t colon = pair.find(':');
        if (colon == std::string::npos) fail("parsing VR:COUNT");
        vrs.push_back(static_cast<fmi3ValueReference>(std::strtoul(pair.c_str(), nullptr, 10)));
        count += std::strtoul(pair.c_str() + colon + 1, nullptr, 10);
    }

    // loggingOn: under FMI 3.0 the FMU says nothing, not even its errors, while it is off.
    fmi3Instance c = fmi3InstantiateCoSimulation("fmi3_host", argv[2], "", fmi3False, fmi3True, fmi3False,
                                                 fmi3False, nullptr, 0, nullptr, log_message, nullptr);
    if (!c) fail("fmi3InstantiateCoSimulation");
    if (std::string(argv[3]) != "-") {
        const fmi3ValueReference nx = 3;
        const fmi3UInt64 value = std::strtoull(argv[3], nullptr, 10);
        check(fmi3EnterConfigurationMode(c), "fmi3EnterConfigurationMode");
        check(fmi3SetUInt64(c, &nx, 1, &value, 1), "fmi3SetUInt64");
        check(fmi3ExitConfigurationMode(c), "fmi3ExitConfigurationMode");
    }
    check(fmi3EnterInitializationMode(c, fmi3False, 0, 0, fmi3False, 0), "fmi3EnterInitializationMode");
    check(fmi3ExitInitializationMode(c), "fmi3ExitInitializationMode");

    if (std::string(argv[4]) != "-") {
        std::ifstream in(argv[4], std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.empty()) fail("reading STATE_IN");
        fmi3FMUState state = nullptr;
        check(
            fmi3DeserializeFMUState(c, reinterpret_cast<const fmi3Byte*>(bytes.data()), bytes.size(), &state),
            "fmi3DeserializeFMUState");
        check(fmi3SetFMUState(c, state), "fmi3SetFMUState");
        check(fmi3FreeFMUState(c, &state), "fmi3FreeFMUState");
    }

    FILE* out = std::fopen(argv[8], "w");
    if (!out) fail("opening OUTPUTS");
    std::vector<double> values(count);
    for (int k = 0; k < steps; ++k) {
        fmi3Boolean event = fmi3True, terminate = fmi3True, early = fmi3True;
        fmi3Float64 reached = -1;
        check(fmi3DoStep(c, t0 + k * h, h, fmi3True, &event, &terminate, &early, &reached), "fmi3DoStep");
        // The FMU's time is its own sum of steps: t0 + (k + 1) h up to round-off.
        if (event || terminate || early || std::abs(reached - (t0 + (k + 1) * h)) > 1e-12)
            fail("fmi3DoStep's flags");
        check(fmi3GetFloat64(c, vrs.data(), vrs.size(), values.data(), values.size()), "fmi3GetFloat64");
        for (size_t i = 0; i < values.size(); ++i) std::fprintf(out, i ? " %a" : "%a", values[i]);
        std::fprintf(out, "\n");
    }
    std::fclose(out);

    fmi3FMUState state = nullptr;
    check(fmi3GetFMUState(c, &state), "fmi3GetFMUState");
    size_t size = 0;
    check(fmi3SerializedFMUStateSize(c, state, &size), "fmi3SerializedFMUStateSize");
    std::vector<fmi3Byte> bytes(size);
    check(fmi3SerializeFMUState(c, state, bytes.data(), size), "fmi3SerializeFMUState");
    check(fmi3FreeFMUState(c, &state), "fmi3FreeFMUState");
    std::ofstream(argv[9], std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(size));
    check(fmi3Terminate(c), "fmi3Terminate");
    fmi3FreeInstance(c);
    return 0;
}
