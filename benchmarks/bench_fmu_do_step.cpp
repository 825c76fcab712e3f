// The FMU's own cost per doStep (issue 44), without an interpreter: loads the FMU's binary
// (tests_cpp/fmi_host.hpp), sets its parameters in Initialization Mode, takes 50 unmeasured
// steps, then 3 rounds of STEPS doSteps of DT, each followed by one fmi2GetReal of OUTPUTS,
// as benchmarks/contact_profile.py does through fmpy. Prints one JSON object: CPU
// microseconds per doStep (median of the rounds), and per fmi2GetReal alone.
//   bench_fmu_do_step LIBRARY GUID DT STEPS OUTPUTS [i:VR=VALUE | r:VR=VALUE]...
// OUTPUTS: comma-separated value references.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "fmi_host.hpp"

namespace {

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
    return x[x.size() / 2];
}

int fail(const char* what) {
    std::fprintf(stderr, "bench_fmu_do_step: %s\n", what);
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr,
                     "usage: bench_fmu_do_step LIBRARY GUID DT STEPS OUTPUTS [i:VR=VALUE | r:VR=VALUE]...\n");
        return 2;
    }
    void* lib = host::load_library(argv[1]);
    if (!lib) return 2;
#define LOAD(f)                                                  \
    auto* f = reinterpret_cast<f##TYPE*>(host::symbol(lib, #f)); \
    if (!f) return fail(#f)
    LOAD(fmi2Instantiate);
    LOAD(fmi2SetupExperiment);
    LOAD(fmi2EnterInitializationMode);
    LOAD(fmi2ExitInitializationMode);
    LOAD(fmi2DoStep);
    LOAD(fmi2GetReal);
    LOAD(fmi2SetReal);
    LOAD(fmi2SetInteger);
    LOAD(fmi2Terminate);
    LOAD(fmi2FreeInstance);
#undef LOAD
    const double dt = std::atof(argv[3]);
    const int steps = std::atoi(argv[4]);
    std::vector<fmi2ValueReference> outputs;
    for (const char* p = argv[5]; *p;) {
        char* end = nullptr;
        outputs.push_back(static_cast<fmi2ValueReference>(std::strtoul(p, &end, 10)));
        p = *end == ',' ? end + 1 : end;
    }
    std::vector<double> values(outputs.size());

    fmi2CallbackFunctions callbacks = {host::logger, nullptr, nullptr, nullptr, nullptr};
    fmi2Component c =
        fmi2Instantiate("bench", fmi2CoSimulation, argv[2], "", &callbacks, fmi2False, fmi2False);
    if (!c) return fail("instantiate");
    if (fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK)
        return fail("setup");
    for (int a = 6; a < argc; ++a) {
        const std::string arg = argv[a];
        const size_t eq = arg.find('=');
        if (arg.size() < 4 || arg[1] != ':' || eq == std::string::npos) return fail("bad setter");
        const auto vr = static_cast<fmi2ValueReference>(std::stoul(arg.substr(2, eq - 2)));
        const std::string value = arg.substr(eq + 1);
        const fmi2Status status = arg[0] == 'i' ? [&] {
            const fmi2Integer v = std::stoi(value);
            return fmi2SetInteger(c, &vr, 1, &v);
        }()
                                                : [&] {
                                                      const fmi2Real v = std::stod(value);
                                                      return fmi2SetReal(c, &vr, 1, &v);
                                                  }();
        if (status != fmi2OK) return fail(arg.c_str());
    }
    if (fmi2ExitInitializationMode(c) != fmi2OK) return fail("exit initialization");

    long k = 0;
    for (; k < 50; ++k)
        if (fmi2DoStep(c, static_cast<double>(k) * dt, dt, fmi2True) != fmi2OK) return fail("doStep");
    std::vector<double> per_step, per_get;
    for (int round = 0; round < 3; ++round) {
        double t0 = cpu_seconds();
        for (int j = 0; j < steps; ++j, ++k) {
            if (fmi2DoStep(c, static_cast<double>(k) * dt, dt, fmi2True) != fmi2OK) return fail("doStep");
            if (fmi2GetReal(c, outputs.data(), outputs.size(), values.data()) != fmi2OK)
                return fail("getReal");
        }
        per_step.push_back((cpu_seconds() - t0) / steps * 1e6);
        t0 = cpu_seconds();
        for (int j = 0; j < steps; ++j)
            if (fmi2GetReal(c, outputs.data(), outputs.size(), values.data()) != fmi2OK)
                return fail("getReal");
        per_get.push_back((cpu_seconds() - t0) / steps * 1e6);
    }
    std::printf("{\"do_step_us\": %.6g, \"get_real_us\": %.6g}\n", median(per_step), median(per_get));
    fmi2Terminate(c);
    fmi2FreeInstance(c);
    return 0;
}
