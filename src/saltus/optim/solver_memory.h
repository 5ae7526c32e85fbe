#pragma once
/// @file
/// A process-wide memory setting for programs that optimise: each program's main calls it once
/// (saltus, saltus-gui, the benchmarks); the library never changes the process on its own.

namespace saltus {

/// Keeps the memory the linear solver frees in the heap instead of returning it to the kernel.
/// MUMPS allocates its frontal matrices afresh for every factorization; with glibc's defaults
/// they are mmap'ed and unmapped each time and every iteration page-faults them in again
/// (measured: docs/performance.md, "MUMPS's fronts kept in the heap"). Memory peaks stay
/// mapped, which for a process that optimises again is what is wanted. No effect off glibc.
void keep_solver_memory_in_heap();

}  // namespace saltus
