// Shell mechanics speed (make bench): force evaluations and FIRE iterations per second for one
// shell of 642, 2562 and 10242 vertices (SVK + hinge-uniform + turgor), on the threads given
// by OMP_NUM_THREADS, and the time to inflate a 2562-vertex shell to equilibrium.
// Prints "name,value,unit" rows.
#include "shell/relax.hpp"
#include "shell/shell_model.hpp"

#include "spheremesh/subdivision.hpp"

#include <chrono>
#include <cstdio>

using namespace cmp;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main() {
  shell::ShellModel m;
  m.bending = "hinge-uniform";
  m.pressure = "turgor";
  m.material = {25.0, 1.0 / 3.0, 0.1};
  m.load.turgor = 0.25;
  for (int level : {4, 5, 6}) {
    const auto rest = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, 2.5);
    auto s = shell::make_shell_system(rest, m);
    Eigen::VectorXd x = 1.01 * s.x, f;
    const long reps = 20000000 / rest.F.rows();
    auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < reps; ++k) s.forces(x, f);
    const double per = seconds_since(t0) / reps;
    std::printf("force_evaluations_%ld,%.1f,1/s\n", static_cast<long>(rest.V.rows()), 1.0 / per);
    std::printf("triangle_forces_%ld,%.3g,1/s\n", static_cast<long>(rest.V.rows()), rest.F.rows() / per);
    shell::RelaxParameters rp;
    rp.force_scale = shell::default_force_scale(rest, m.material.youngs_modulus, m.material.thickness);
    rp.relative_tolerance = 1e-9;
    t0 = std::chrono::steady_clock::now();
    const auto r = shell::relax(s, rp);
    const double sec = seconds_since(t0);
    std::printf("fire_iterations_per_s_%ld,%.1f,1/s\n", static_cast<long>(rest.V.rows()), r.iterations / sec);
    if (level == 5) std::printf("inflate_2562_to_equilibrium,%.3f,s (%ld FIRE iterations)\n", sec, r.iterations);
  }
}
