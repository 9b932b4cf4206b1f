#pragma once
// Benchmark B.7 (Fig. B.10): a spherical shell under growing external pressure, and the
// pressure at which it buckles, in units of the classical p_c = 4 sqrt(kappa Y)/R0^2
// (elasticity/buckling.hpp).
//
// The model is the thesis's: Seung-Nelson springs (Y = E t, nu = 1/3) and normal-vector
// bending springs. The bending style is hinge-uniform, whose kappa is the mechanical bending
// rigidity E t^3/(12 (1 - nu^2)) (the Cylinder calibration; the default `hinge` style bends 3x
// stiffer, see elasticity/buckling.hpp), the calibration of Paulose et al., on whom Fig. B.10
// is based. E = 1 and R0 = 1 (the result is scale-free); t follows from the Foppl-von Karman
// number gamma = Y R0^2/kappa = 12 (1 - nu^2)(R0/t)^2.
//
// Protocol (the thesis raises p in steps of 0.0025 p_c and watches for a sudden volume drop):
// starting from the relaxed, unloaded sphere, p/p_c goes up in coarse steps (`step`), each
// relaxed by FIRE from the last stable state. A step buckles when the volume falls more than
// `volume_drop` below the volume of the last stable step (the relaxation is stopped there: a
// shell past its buckling pressure collapses through itself, nothing stops it). The bracket
// [last stable, first buckled] is then halved, always restarting from the last stable state,
// until it is narrower than `resolution` (0.0025, the thesis's step): the same answer as the
// thesis's fine stepping, at a few relaxations instead of hundreds.
//
// Before every relaxation each vertex is displaced by a random vector of length up to
// kick * t (a seeded, reproducible stream): an imperfection-free state (the icosahedral mesh is
// symmetric) would otherwise stay on the unstable symmetric branch past p_c. The kick is a
// state perturbation, not a change of the rest mesh: below the buckling pressure it decays.
#include "mesh/tri_mesh.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace cmp::shellbench {

struct BucklingCase {
  double gamma = 1e4;                 // Foppl-von Karman number Y R0^2/kappa
  std::string stretching = "springs-seung-nelson";
  std::string bending = "hinge-uniform";
  double step = 0.05;                 // coarse p/p_c step
  double resolution = 0.0025;         // final bracket width in p/p_c
  double max_pressure = 1.6;          // give up (no buckling) beyond this p/p_c
  double volume_drop = 0.03;          // buckled: V < (1 - this) V of the last stable step
  double kick = 1e-3;                 // random displacement before each relaxation [t]
  std::uint64_t seed = 1;
  double relative_tolerance = 1e-7;   // FIRE: max |f_i| <= this * E t a
  long max_iterations = 400'000;      // FIRE iterations per relaxation
  // Throws cmp::UsageError naming the first bad field.
  void validate() const;
};

struct BucklingResult {
  bool buckled = false;        // false: stable up to max_pressure
  double pressure = 0;         // p/p_c of the first buckled relaxation (upper end of the bracket)
  double stable_pressure = 0;  // p/p_c of the last stable one (lower end)
  double stable_volume = 0;    // V/V0 at stable_pressure
  // How far the last stable state is from a sphere: the rms over the vertices of |x_i| minus
  // its mean, in units of t (0 at rest: every vertex starts on the sphere). A non-uniform
  // membrane stress (springs on unequal triangles) makes the loaded shell wavy: an imperfection.
  double stable_roughness = 0;
  double critical_pressure = 0;  // p_c [E units, R0 = 1]
  double thickness = 0;        // t [R0]
  int relaxations = 0;
  long iterations = 0;         // FIRE iterations over every relaxation
  int unconverged = 0;         // relaxations stopped at max_iterations without buckling
  int nonfinite = 0;           // relaxations counted as buckled because a force became non-finite
                               // (elements crushed flat by the collapse between two volume checks)
};

// Runs the protocol above on `rest` (a closed, outward-oriented sphere mesh of radius about 1
// centred at the origin). note(text) reports each relaxation. Throws cmp::UsageError for a bad
// mesh or case.
BucklingResult buckling_run(const mesh::TriMesh& rest, const BucklingCase& c,
                            const std::function<void(const std::string&)>& note = {});

}  // namespace cmp::shellbench
