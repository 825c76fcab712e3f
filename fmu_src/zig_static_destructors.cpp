// zig's linker does not register a shared object's static destructors with __cxa_finalize
// (ziglang/zig#17908): they would run after dlclose, in unmapped code, and crash the host at
// its exit. Running them when the library is unloaded is what a gcc-linked .so does.
extern "C" void __cxa_finalize(void*);
extern "C" void* __dso_handle;

__attribute__((destructor)) static void run_static_destructors() { __cxa_finalize(&__dso_handle); }
