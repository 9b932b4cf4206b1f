#pragma once
// Jammed packings of Hertzian spheres by the thesis's protocol (Section 5.5.1;
// where the text is silent, docs/thesis-departures.md says what was chosen): random centres in a periodic cube at volume fraction 0.01, then
// radii scaled by (1 + eps_r) or (1 - eps_r), each change followed by FIRE, inflating while
// P < P_min and deflating while P > 2 P_min, with eps_r halved at every reversal, until
// P_min < P < 2 P_min. A packing with rattlers is rejected and the whole procedure restarts
// from new random centres. So, by default, is a packing that is not isostatic (3N - 2
// contacts in a periodic box): small boxes crystallise now and then (N = 16: about one
// packing in ten orders at phi = 0.692 with 56 contacts), which the thesis's Fig. S5.1
// (Z = 6 - 4/N) and Fig. S5.2 do not count as random jammed packings.
#include "minimise/fire.hpp"
#include "forcefield/hertz.hpp"
#include "spheres/sphere_packing.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace cmp::spheres {

struct JammingParameters {
  double initial_volume_fraction = 0.01;  // psi_0
  double initial_step = 0.01;             // eps_r
  // Relative standard deviation of the radii (0: monodisperse, the thesis's packings). The
  // relative sizes are drawn uniformly from [1 - sqrt(3) p, 1 + sqrt(3) p] (whose standard
  // deviation is p) after the centres of each try and rescaled to mean 1; every size change
  // scales all radii by the same factor, so the size ratios are those drawn. At most 0.25.
  double polydispersity = 0;
  double min_pressure = 1e-8;             // P_min, in units of E
  HertzMaterial material;                 // E = 1, nu = 0.5
  minimise::FireParameters fire;          // the thesis's FIRE; tolerance below
  int max_tries = 1000;                   // packings started before giving up
  long max_size_changes = 20000;          // per try
  bool reject_rattlers = true;
  bool require_isostatic = true;          // reject packings without exactly 3N - 2 contacts
  // FIRE iterations allowed after each size change before the protocol moves on unrelaxed
  // (0: relax every step to the tolerance, quasi-static), as an iteration-capped FIRE in the
  // author's code would; the final packing is always relaxed to the tolerance before it is
  // judged. A cap does NOT make a run faster: every minimisation starts FIRE from rest (v = 0,
  // dt = dt_FIRE, alpha = alpha_start), so a relaxation cut into pieces of `cap` iterations
  // loses the growth of the time step that makes one continuous FIRE run fast, and the
  // pressure judged after a capped step is that of an unrelaxed state, which reverses the
  // protocol (halving eps_r) on transients. Measured with `shellpack jam --seed 1`: N = 16,
  // cap 200: 7.2e5 FIRE iterations against 2.0e4 uncapped; N = 32, cap 200: 3.5e6 against
  // 1.5e5 and 7433 size changes against 153 (13 times the time); N = 16, cap 20 never reaches
  // the pressure window. Steps that converge within the cap are the same as uncapped.
  long step_iteration_cap = 0;
  JammingParameters() { fire.force_tolerance = 1e-15; }  // the thesis's max|f_i| <= 1e-15
  // Throws cmp::UsageError naming the first bad value.
  void validate() const;
};

// Why a try was not accepted.
enum class TryOutcome { Accepted, Rattlers, NotIsostatic, NoPressureWindow, FireCap };
std::string try_outcome_name(TryOutcome outcome);

struct JammingResult {
  SpherePacking packing;    // centres wrapped into [0, L)^3; equal radii unless polydisperse
  double pressure = 0;      // in units of E
  double energy = 0;
  double max_force = 0;     // max |f_i| at the end
  int contacts = 0;         // touching pairs
  int rattlers = 0;         // 0 unless reject_rattlers is off
  long fire_iterations = 0; // over every try
  long size_changes = 0;    // of the accepted try
  int rejected_tries = 0;   // tries thrown away, for any reason; by reason:
  int rejected_for_rattlers = 0;
  int rejected_not_isostatic = 0;
  int rejected_no_pressure_window = 0;  // max_size_changes or a vanishing eps_r before the window
  int rejected_fire_cap = 0;            // a FIRE minimisation hit its iteration cap
  double seconds = 0;       // wall time
  double contact_number() const { return packing.size() ? 2.0 * contacts / packing.size() : 0.0; }
};

// The side of the cube: chosen so that the diameter is about 1 at jamming (L^3 = N pi / (6 *
// 0.64)); the result does not depend on it (Hertz pressure is scale-free in units of E).
double jamming_box_side(int n);

// The largest polydispersity accepted: the smallest sphere is then about 0.57 of the mean.
inline constexpr double kMaxPolydispersity = 0.25;

// Smallest N accepted: below it a sphere at jamming is wider than half the box and would touch
// two images of another, and the minimum image convention (and the thesis's model) breaks.
inline constexpr int kMinJammingSpheres = 10;
// The most spheres a jammed packing is made of: said at the option (-N), before anything is
// allocated (2e9 spheres ended in "out of memory" after the allocation was tried).
inline constexpr int kMaxJammingSpheres = 1000000;

// What the progress callback sees after every size change.
struct JammingProgressInfo {
  int attempt = 0;              // try number, from 0
  long size_changes = 0;        // in this try
  double volume_fraction = 0, pressure = 0;
  int rejected_for_rattlers = 0, rejected_not_isostatic = 0, rejected_no_pressure_window = 0,
      rejected_fire_cap = 0;    // earlier tries of this packing, by reason
};
// Return false to give up (throws cmp::ComputationError("interrupted")).
using JammingProgress = std::function<bool(const JammingProgressInfo&)>;

// Contacts of an isostatic rattler-free packing of n spheres in a periodic box: d(n - 1) + 1.
inline int isostatic_contacts(int n) { return 3 * n - 2; }

// The fraction of tries that end accepted under the rules of p (reject_rattlers,
// require_isostatic) at n spheres, as measured with the default protocol (README, shellpack),
// interpolated in log N between the measured sizes and held constant beyond them. An
// estimate to warn a user by, not a physical law.
double expected_acceptance(int n, const JammingParameters& p);
// A warning for stderr when expected_acceptance makes a packing take 5 tries or more
// ("at N = 256 about 1 try in 60 is accepted ..."); "" otherwise.
std::string acceptance_warning(int n, const JammingParameters& p);

// One accepted jammed packing of n spheres. Try k draws its centres from Random(seed, k), so
// the result depends on (n, seed, parameters) only, never on threads or timing. Throws
// cmp::UsageError for n < kMinJammingSpheres or bad parameters, cmp::ComputationError when
// max_tries tries all fail.
JammingResult jam_spheres(int n, std::uint64_t seed, const JammingParameters& parameters,
                          const JammingProgress& progress = {});

}  // namespace cmp::spheres
