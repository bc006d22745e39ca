#pragma once
// A kernel compiled twice, for x86-64 processors with the FMA instructions and for the others,
// the right one chosen once when the program loads (GCC's target_clones, glibc's ifunc). Every
// std::fma of the exact arithmetic is then one instruction, where without -mfma it is a call
// into libm that also spills every live register. The results are the same bits: fma is
// correctly rounded either way, and -ffp-contract=off keeps the compiler from fusing anything
// else. Elsewhere (WebAssembly, clang, the sanitizer builds) a plain function.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(__SANITIZE_ADDRESS__)
#define EPURE_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define EPURE_FMA_CLONES
#endif

// The same for a kernel, with what it calls in its own file compiled into it (flatten): a
// helper left out of line would be compiled once, for the default target only.
#define EPURE_FMA_KERNEL EPURE_FMA_CLONES __attribute__((flatten))
