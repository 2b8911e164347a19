#pragma once
// SCULPT_KERNEL_TARGET compiles an element kernel for AVX-512VL where the build's CPU has it
// (CMakeLists.txt defines SCULPT_KERNEL_AVX512VL then). The kernels stay four lanes wide; what
// they gain is the 32 vector registers instead of 16, so that a Gauss-point group's values
// spill less. The rest of the program keeps AVX2, whose Eigen code compiles without warnings.
#if defined(SCULPT_KERNEL_AVX512VL) && defined(__GNUC__)
#define SCULPT_KERNEL_TARGET __attribute__((target("avx512f,avx512vl")))
#else
#define SCULPT_KERNEL_TARGET
#endif
