// A minimal FMI 2.0 host that continues a simulation from a serialized FMU state, on any
// platform (python_tests/test_windows.py runs its win64 build under wine,
// python_tests/test_aarch64.py its aarch64 build under qemu): it loads the FMU binary, sets
// the parameters given as --real VR=VALUE and --integer VR=VALUE (the rest keep their
// defaults), initializes, restores the state from STATE_IN (unless "-"), takes STEPS steps of H
// from T0, writes the value references' reals after each step as hex floats (one line a step)
// to OUTPUTS, and the final state, serialized, to STATE_OUT.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "fmi_host.hpp"

namespace {

using host::logger;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "state_host: %s failed\n", what);
    std::exit(1);
}

void check(fmi2Status status, const char* what) {
    if (status != fmi2OK) fail(what);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::pair<fmi2ValueReference, double>> reals;
    std::vector<std::pair<fmi2ValueReference, int>> integers;
    while (argc > 2 && (std::string(argv[1]) == "--real" || std::string(argv[1]) == "--integer")) {
        char* end = nullptr;
        const auto vr = static_cast<fmi2ValueReference>(std::strtoul(argv[2], &end, 10));
        if (*end != '=') fail("reading a parameter (--real VR=VALUE, --integer VR=VALUE)");
        if (std::string(argv[1]) == "--real")
            reals.emplace_back(vr, std::strtod(end + 1, nullptr));
        else
            integers.emplace_back(vr, std::atoi(end + 1));
        argc -= 2;
        argv += 2;
    }
    if (argc < 9) {
        std::fprintf(stderr,
                     "usage: state_host [--real VR=VALUE | --integer VR=VALUE]... LIBRARY GUID "
                     "STATE_IN|- T0 STEPS H OUTPUTS STATE_OUT VR...\n");
        return 2;
    }
    void* library = host::load_library(argv[1]);
    if (!library) fail("loading the library");
#define LOAD(f)                                                      \
    auto* f = reinterpret_cast<f##TYPE*>(host::symbol(library, #f)); \
    if (!f) fail(#f)
    LOAD(fmi2Instantiate);
    LOAD(fmi2SetupExperiment);
    LOAD(fmi2EnterInitializationMode);
    LOAD(fmi2ExitInitializationMode);
    LOAD(fmi2DoStep);
    LOAD(fmi2GetReal);
    LOAD(fmi2SetReal);
    LOAD(fmi2SetInteger);
    LOAD(fmi2GetFMUstate);
    LOAD(fmi2SetFMUstate);
    LOAD(fmi2FreeFMUstate);
    LOAD(fmi2SerializedFMUstateSize);
    LOAD(fmi2SerializeFMUstate);
    LOAD(fmi2DeSerializeFMUstate);
    LOAD(fmi2Terminate);
    LOAD(fmi2FreeInstance);
#undef LOAD
    const double t0 = std::strtod(argv[4], nullptr), h = std::strtod(argv[6], nullptr);
    const int steps = std::atoi(argv[5]);
    std::vector<fmi2ValueReference> vrs;
    for (int i = 9; i < argc; ++i)
        vrs.push_back(static_cast<fmi2ValueReference>(std::strtoul(argv[i], nullptr, 10)));

    fmi2CallbackFunctions callbacks = {logger, nullptr, nullptr, nullptr, nullptr};
    fmi2Component c =
        fmi2Instantiate("state_host", fmi2CoSimulation, argv[2], "", &callbacks, fmi2False, fmi2False);
    if (!c) fail("fmi2Instantiate");
    for (const auto& [vr, value] : reals) check(fmi2SetReal(c, &vr, 1, &value), "fmi2SetReal");
    for (const auto& [vr, value] : integers) check(fmi2SetInteger(c, &vr, 1, &value), "fmi2SetInteger");
    check(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), "fmi2SetupExperiment");
    check(fmi2EnterInitializationMode(c), "fmi2EnterInitializationMode");
    check(fmi2ExitInitializationMode(c), "fmi2ExitInitializationMode");

    if (std::string(argv[3]) != "-") {
        std::ifstream in(argv[3], std::ios::binary);
        std::vector<fmi2Byte> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.empty()) fail("reading STATE_IN");
        fmi2FMUstate state = nullptr;
        check(fmi2DeSerializeFMUstate(c, bytes.data(), bytes.size(), &state), "fmi2DeSerializeFMUstate");
        check(fmi2SetFMUstate(c, state), "fmi2SetFMUstate");
        check(fmi2FreeFMUstate(c, &state), "fmi2FreeFMUstate");
    }

    FILE* out = std::fopen(argv[7], "w");
    if (!out) fail("opening OUTPUTS");
    std::vector<double> values(vrs.size());
    for (int k = 0; k < steps; ++k) {
        check(fmi2DoStep(c, t0 + k * h, h, fmi2True), "fmi2DoStep");
        check(fmi2GetReal(c, vrs.data(), vrs.size(), values.data()), "fmi2GetReal");
        for (size_t i = 0; i < values.size(); ++i) std::fprintf(out, i ? " %a" : "%a", values[i]);
        std::fprintf(out, "\n");
    }
    std::fclose(out);

    fmi2FMUstate state = nullptr;
    check(fmi2GetFMUstate(c, &state), "fmi2GetFMUstate");
    size_t size = 0;
    check(fmi2SerializedFMUstateSize(c, state, &size), "fmi2SerializedFMUstateSize");
    std::vector<fmi2Byte> bytes(size);
    check(fmi2SerializeFMUstate(c, state, bytes.data(), size), "fmi2SerializeFMUstate");
    check(fmi2FreeFMUstate(c, &state), "fmi2FreeFMUstate");
    std::ofstream(argv[8], std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(size));
    check(fmi2Terminate(c), "fmi2Terminate");
    fmi2FreeInstance(c);
    return 0;
}
