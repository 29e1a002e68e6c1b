// Which of Embree's kernels cast the sensors' rays.
#pragma once

#include <string>
#include <vector>

namespace bullet_plant
{
// Embree has its kernels once per instruction set (Debian's build: sse2, sse4.2, avx, avx2, avx512;
// 4-wide SSE, 8-wide AVX, 16-wide AVX-512) and runs the widest the CPU has, so a machine exercises
// only one of them. The environment variable TIANRACER_EMBREE_ISA names one to use instead, for
// the scenes made after it is set (a world makes its scene when a sensor first casts): tests run
// every ISA the machine has with it, and benchmarks compare them.
constexpr const char* kEmbreeIsaVariable = "TIANRACER_EMBREE_ISA";
struct EmbreeIsa
{
  std::string name;     // the ISA a new scene's kernels use
  bool forced = false;  // named by TIANRACER_EMBREE_ISA (else the widest the CPU has, as Embree picks)
  std::string problem;  // why TIANRACER_EMBREE_ISA could not be followed, or empty
};
EmbreeIsa embreeIsa();
// The instruction sets of Embree's kernels this CPU can run, narrowest first.
std::vector<std::string> embreeIsasThisCpuRuns();

}  // namespace bullet_plant
