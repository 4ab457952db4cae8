// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The instruction set of the loops that run for every plane hypothesis: the
// draw of triples (`Points_sampler`, and `Weighted_points_sampler` for
// RRHT_Cubes and RRHT_Unif) and the planes of a batch (`Plane_batch`); of
// the rotation of a neighborhood for each accumulator (`rotate()`);
// and of the lattice of RRHT_Unif, for each neighborhood (`Unif_sampler`).
// They also get an AVX2 version, chosen at run time, that gives the same
// results as the baseline one, bit for bit.

#ifndef CGAL_RRHT_INTERNAL_INSTRUCTION_SET_H
#define CGAL_RRHT_INTERNAL_INSTRUCTION_SET_H

/// \def CGAL_RRHT_AVX2_KERNELS
/// 1 when these loops are compiled twice, for the target of the build and
/// for AVX2, and the AVX2 version runs on processors that have it. A build
/// for a generic x86-64 target (SSE2, the default of compilers and of Linux
/// distributions) otherwise uses 4 of the 8 lanes of today's processors.
///
/// Only elementwise IEEE operations (+, -, *, /, sqrt, comparisons, integer
/// arithmetic) are vectorized wider, and the AVX2 target does not include
/// FMA, so the compiler cannot contract a * b + c: both versions give the
/// same bits (tested). Eigen's own vectorization, fixed when it is
/// compiled, is the same in both.
///
/// GCC on x86-64 (the `target` attribute and `__builtin_cpu_supports()`),
/// unless the build already targets AVX2 or `CGAL_RRHT_NO_AVX2_KERNELS` is
/// defined; otherwise 0, and the loops are those of the build's target.
#if !defined(CGAL_RRHT_NO_AVX2_KERNELS) && defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(__AVX2__)
#  define CGAL_RRHT_AVX2_KERNELS 1
#else
#  define CGAL_RRHT_AVX2_KERNELS 0
#endif

namespace CGAL {
namespace RRHT {
namespace internal {

/// The instruction sets of the loops of `Points_sampler`, `Weighted_points_sampler`,
/// `Unif_sampler`, `Plane_batch` and `rotate()`.
enum class Instruction_set
{
  baseline, ///< the target of the build
  avx2      ///< AVX2, without FMA: only where `best_instruction_set()` gives it
};

/// The widest of the instruction sets that this build has and this
/// processor runs (the answer of the processor is read once).
inline Instruction_set best_instruction_set()
{
#if CGAL_RRHT_AVX2_KERNELS
  static const bool has_avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has_avx2 ? Instruction_set::avx2 : Instruction_set::baseline;
#else
  return Instruction_set::baseline;
#endif
}

#if CGAL_RRHT_AVX2_KERNELS
// `loop()` compiled for AVX2: `flatten` inlines it, and all it calls, here.
template <typename Loop>
__attribute__((target("avx2"), flatten)) void run_for_avx2(const Loop& loop)
{
  loop();
}
#endif

/// Runs `loop()`, a loop of `Points_sampler`, `Weighted_points_sampler`,
/// `Unif_sampler`, `Plane_batch` or `rotate()`, compiled for
/// `instruction_set`.
template <typename Loop>
void run_with(Instruction_set instruction_set, const Loop& loop)
{
#if CGAL_RRHT_AVX2_KERNELS
  if(instruction_set == Instruction_set::avx2)
    return run_for_avx2(loop);
#endif
  (void)instruction_set;
  loop();
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_INSTRUCTION_SET_H
