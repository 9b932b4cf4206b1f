// Linked into every program, benchmark and test executable of the toolkit (not into the
// library): OpenMP's wait policy, set before the OpenMP runtime starts.
//
// Why: libgomp's default lets a thread that reaches a barrier spin for about a millisecond
// before it sleeps. When another process holds one of the cores (make -j, a shared node),
// the spinning thread keeps its core busy while the thread it waits for is descheduled: FIRE
// on 4096 spheres took 6-8 times longer on 2 threads than on one. A sleeping wait costs a few
// microseconds per parallel region and keeps two threads at least as fast as one under load
// (README, "Threads under load": the measurement that chose this).
//
// How: libgomp reads OMP_WAIT_POLICY once, in its own initialiser, which runs before main()
// and before the program's constructors. Functions in .preinit_array run before every shared
// library's initialiser, so the default is set there. A value the user exported wins
// (setenv with overwrite = 0), as does GOMP_SPINCOUNT.
#include <cstdlib>

namespace {

void set_openmp_defaults(int, char**, char**) {
  if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT")) setenv("OMP_WAIT_POLICY", "passive", 0);
}

}  // namespace

__attribute__((section(".preinit_array"), used)) static void (*const cmp_preinit_openmp)(int, char**, char**) =
    set_openmp_defaults;
