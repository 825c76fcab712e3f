// What the benchmark programs share: the clock, peak memory, and the paper scene from the
// command line (NX DT, the scene's substep size).
#pragma once

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

#include "assembly/discretization.hpp"

namespace bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Peak resident memory of this process image in MB (VmHWM; ru_maxrss would include the
// parent's peak, which survives execve).
inline double peak_rss_mb() {
    std::ifstream status("/proc/self/status");
    std::string key;
    double kb = 0;
    while (status >> key) {
        if (key == "VmHWM:") {
            status >> kb;
            break;
        }
    }
    return kb / 1024.0;
}

// The paper scene with nx = ny = NX (argv[1]) and substep DT (argv[2]).
inline contactbody::SceneParameters paper_scene(char** argv) {
    contactbody::SceneParameters p;
    p.nx = p.ny = std::atoi(argv[1]);
    p.internal_step = std::atof(argv[2]);
    return p;
}

}  // namespace bench
