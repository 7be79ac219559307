// Function multiversioning for the hot kernels: GCC compiles a function marked
// CRUMPLE_TARGET_CLONES for AVX-512, AVX2 and baseline x86-64 and picks one at load time. Clang
// (the fuzz build, which compiles the material laws for their card readers) does not support
// target_clones on function templates, and the fuzz build does not need the speed: there the
// macro is empty. Every clone computes the same IEEE operations (-ffp-contract=off), so the
// results do not depend on the clone.
#pragma once

#if defined(__clang__)
#define CRUMPLE_TARGET_CLONES
#else
#define CRUMPLE_TARGET_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#endif
