#pragma once
// GRANMIX_VECTOR_CLONES: a function built for AVX-512 and AVX2 as well as the x86-64 baseline, chosen at run time
// (GCC/Clang target_clones). Only for loops whose numbers cannot depend on the build: elementwise IEEE +, ×, ÷ and √
// (each rounds once) and sums in a fixed order, in a file compiled without FMA contraction (-ffp-contract=off,
// theory/CMakeLists.txt).
#if defined(__x86_64__)
#define GRANMIX_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define GRANMIX_VECTOR_CLONES
#endif
