#pragma once
// Large deflection of a clamped circular plate under a uniform pressure q, solved numerically
// from the axisymmetric von Karman plate equations (no approximation of the deflected shape,
// unlike Eq. B.88): with phi = dw/dr, M = (1/r)(r phi)' and the radial membrane force N_r,
//   D M' = q r/2 + N_r phi                     (transverse equilibrium)
//   r [ (1/r)(r^2 N_r)' ]' = -(E t/2) phi^2    (compatibility)
// clamped (w = 0, phi = 0) and immovable (radial displacement u = r (N_theta - nu N_r)/(E t) = 0,
// N_theta = (r N_r)') at r = R0, regular at r = 0. Solved by multiple shooting over 8 equal
// segments (the unknowns: the centre's curvature and tension and the state at each inner node;
// short segments keep the growing mode of the edge's bending layer in check), RK8(9) and GSL's
// hybrid root finder, with continuation in load (steps of 10 %; 0.3 s from P* = 0 to 1e4).
// Against B.88: within 2 % at nu = 0 (6.998 against 7.119 at P* = 1e3), within 3.3 % at
// nu = 0.3 (1.052 against 1.019 at P* = 10); at nu = 0.3 it tends to Hencky's membrane value
// from below (0.967, 0.974, 0.979 of it at P* = 1e3, 3e3, 1e4).
// w/t depends on P* = (q/E)(R0/t)^4 and nu only. Limits: w/t -> (12 (1 - nu^2)/64) P* (B.87) at
// small load; the membrane solution (Hencky: w/R0 = 0.662 (q R0/(E t))^(1/3) at nu = 0.3) at
// large load. Units: dimensionless (w_max/t, P*).
#include <vector>

namespace cmp::elasticity {

// w_max/t for each P* of `load_stars` (positive, increasing), nu in (-1, 0.5). Throws
// std::domain_error for bad arguments, cmp::ComputationError when the root finder fails.
std::vector<double> von_karman_max_deflection(double poisson_ratio, const std::vector<double>& load_stars);

}  // namespace cmp::elasticity
