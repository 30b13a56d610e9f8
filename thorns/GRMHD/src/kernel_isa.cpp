#include "kernel_isa.hpp"

namespace remnant::grmhd {
namespace {

bool cpu_has_avx2() {
#if REMNANT_HAVE_AVX2_KERNELS
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}
bool& portable_forced() {
  static bool forced = false;
  return forced;
}

}  // namespace

bool avx2_kernels() {
  static const bool has = cpu_has_avx2();
  return has && !portable_forced();
}

void use_portable_kernels(bool on) { portable_forced() = on; }

}  // namespace remnant::grmhd
