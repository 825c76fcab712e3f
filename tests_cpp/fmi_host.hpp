// What the small FMI hosts of the tests share: a logger that prints, and loading the FMU's
// binary and its functions on Linux (dlopen) and Windows (LoadLibrary).
#pragma once

#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

#include <cstdarg>
#include <cstdio>

extern "C" {
#include "fmi2Functions.h"
}

namespace host {

inline void logger(fmi2ComponentEnvironment, fmi2String instance, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    va_list args;
    va_start(args, message);
    std::fprintf(stderr, "[%s %d %s] ", instance, static_cast<int>(status), category);
    std::vfprintf(stderr, message, args);
    std::fprintf(stderr, "\n");
    va_end(args);
}

// The library, or nullptr (the reason printed).
inline void* load_library(const char* path) {
#ifdef _WIN32
    void* library = reinterpret_cast<void*>(LoadLibraryA(path));
    if (!library) std::fprintf(stderr, "LoadLibrary(%s) failed (error %lu)\n", path, GetLastError());
#else
    void* library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!library) std::fprintf(stderr, "%s\n", dlerror());
#endif
    return library;
}

inline void* symbol(void* library, const char* name) {
#ifdef _WIN32
    return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(library), name));
#else
    return dlsym(library, name);
#endif
}

}  // namespace host
