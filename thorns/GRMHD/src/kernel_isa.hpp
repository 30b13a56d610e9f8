#pragma once
// Run-time choice of the instruction set of the hot sweep and source kernels (rhs.cpp,
// mhd_fluxes.cpp). The portable build targets SSE2 (two doubles per vector); on a CPU with AVX2 the
// same source is compiled a second time inside functions marked REMNANT_AVX2_KERNEL (four doubles
// per vector, three-operand instructions) and chosen at run time. AVX2 alone, without FMA: GCC
// contracts a * b + c into an FMA by default in C++ (-ffp-contract=fast) wherever FMA is enabled,
// which changes the bits (KernelIsa.* fail with "avx2,fma"); without it both versions compute the
// same operations and give the same bits (the bench checksums and KernelIsa.* hold them). The AVX2 wrappers are [[gnu::flatten]]: every callee is
// inlined into them, so no out-of-line AVX2 copy of a shared inline function can reach the
// portable path.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX2__)
#define REMNANT_HAVE_AVX2_KERNELS 1
#define REMNANT_AVX2_KERNEL [[gnu::target("avx2"), gnu::flatten]]
#else
#define REMNANT_HAVE_AVX2_KERNELS 0
#endif

namespace remnant::grmhd {

// True when the AVX2 kernels run: the CPU has AVX2 and use_portable_kernels(true) was not called.
bool avx2_kernels();
// Forces the portable kernels (on) or returns to the CPU's choice (off); for the tests that compare
// the two versions bit for bit. Not thread-safe: call it between steps.
void use_portable_kernels(bool on);

}  // namespace remnant::grmhd
