#include "flowrun/prolong.hpp"

#include "lbm/d3q19.hpp"

#include <cmath>
#include <stdexcept>

namespace cmp::flowrun {

namespace {

// The drive's scale of pressure differences and of velocities on a lattice of n nodes along
// the flow axis.
struct DriveScale {
  double pressure;  // density differences per voxel side: the drop's, or the force's
  double velocity;  // grad p / nu (kappa_lu / M^2 is the same on every lattice)
};

DriveScale drive_scale(const lbm::FlowSettings& s, long n_axis, int M) {
  const double nu = (s.collision_parameters.tau - 0.5) * lbm::kCs2;
  if (s.driving == lbm::Driving::kPressure) {
    const double per_node = s.density_drop / static_cast<double>(n_axis - 1);  // the planes are n - 1 apart
    return {per_node * M, lbm::kCs2 * per_node / nu};
  }
  return {s.body_force / lbm::kCs2 * M, s.body_force / nu};  // grad p = g, p = c_s^2 rho
}

}  // namespace

lbm::StartState prolonged_start(const CoarseFlow& c, int M, const lbm::FlowSettings& s) {
  const int Mc = c.refine;
  const long nc[3] = {static_cast<long>(c.voxels[0]) * Mc, static_cast<long>(c.voxels[1]) * Mc,
                      static_cast<long>(c.voxels[2]) * Mc};
  const long nf[3] = {static_cast<long>(c.voxels[0]) * M, static_cast<long>(c.voxels[1]) * M,
                      static_cast<long>(c.voxels[2]) * M};
  const std::size_t coarse_nodes = static_cast<std::size_t>(nc[0] * nc[1] * nc[2]);
  if (Mc < 1 || M < 1 || c.density.size() != coarse_nodes || c.velocity.size() != 3 * coarse_nodes)
    throw std::invalid_argument("prolonged start: the coarse fields do not match the image refined " +
                                std::to_string(Mc) + " times");
  if (c.settings.driving != s.driving || c.settings.axis != s.axis)
    throw std::invalid_argument("prolonged start: the coarse flow has another drive or flow axis");
  const int a = s.axis;
  const bool pressure = s.driving == lbm::Driving::kPressure;
  const DriveScale from = drive_scale(c.settings, nc[a], Mc), to = drive_scale(s, nf[a], M);
  const double density_ratio = to.pressure / from.pressure;
  const double velocity_ratio = static_cast<double>(M) * M / (static_cast<double>(Mc) * Mc) * to.velocity / from.velocity;
  auto ramp = [pressure](const lbm::FlowSettings& set, long plane, long n) {
    return pressure ? 1 + 0.5 * set.density_drop - set.density_drop * static_cast<double>(plane) / static_cast<double>(n - 1)
                    : 1.0;
  };
  return [&c, Mc, M, nc0 = nc[0], nc1 = nc[1], nc2 = nc[2], nf0 = nf[0], nf1 = nf[1], a, pressure, density_ratio,
          velocity_ratio, ramp, s](long g, double& rho, double u[3]) {
    const long nc[3] = {nc0, nc1, nc2}, nf[3] = {nf0, nf1, 0};
    const long fine[3] = {g % nf[0], g / nf[0] % nf[1], g / nf[0] / nf[1]};
    long lo[3], hi[3];
    double t[3];
    for (int d = 0; d < 3; ++d) {
      // The fine node's centre on the coarse grid: coarse node k is at (k + 1/2) / Mc voxels.
      const double x = (static_cast<double>(fine[d]) + 0.5) * Mc / M - 0.5;
      const double f = std::floor(x);
      t[d] = x - f;
      lo[d] = static_cast<long>(f);
      hi[d] = lo[d] + 1;
      if (d != a || !pressure) {  // periodic
        lo[d] = (lo[d] % nc[d] + nc[d]) % nc[d];
        hi[d] = hi[d] % nc[d];
      } else {  // clamped between the pressure planes
        if (lo[d] < 0) lo[d] = 0, t[d] = 0;
        if (hi[d] > nc[d] - 1) hi[d] = nc[d] - 1, t[d] = 0;
      }
    }
    double w_sum = 0, departure = 0, v[3] = {0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
      long k[3];
      double w = 1;
      for (int d = 0; d < 3; ++d) {
        const bool up = (corner >> d) & 1;
        k[d] = up ? hi[d] : lo[d];
        w *= up ? t[d] : 1 - t[d];
      }
      const std::size_t i = static_cast<std::size_t>(k[0] + nc[0] * (k[1] + nc[1] * k[2]));
      if (w == 0 || c.density[i] == 0) continue;  // a node that takes no part in the coarse flow
      w_sum += w;
      departure += w * (c.density[i] - ramp(c.settings, k[a], nc[a]));
      for (int d = 0; d < 3; ++d) v[d] += w * c.velocity[3 * i + d];
    }
    const long n_axis = a == 0 ? nf0 : a == 1 ? nf1 : static_cast<long>(c.voxels[2]) * M;
    rho = ramp(s, fine[a], n_axis);
    u[0] = u[1] = u[2] = 0;
    if (w_sum == 0) return;  // nothing flows around it on the coarse lattice: at rest
    rho += density_ratio * departure / w_sum;
    for (int d = 0; d < 3; ++d) u[d] = velocity_ratio * v[d] / w_sum;
  };
}

}  // namespace cmp::flowrun
