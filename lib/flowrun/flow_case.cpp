#include "flowrun/flow_case.hpp"

#include "core/errors.hpp"
#include "flowrun/flow_vtk.hpp"
#include "flowrun/pore_cluster.hpp"
#include "flowrun/refine.hpp"
#include "io/input.hpp"
#include "lbm/sphere_lattice.hpp"
#include "voxel/grid.hpp"
#include "packing/packing_file.hpp"
#include "voxel/porosity.hpp"

#include <fmt/format.h>

#include <cmath>

namespace cmp::flowrun {

namespace {

void require_cluster(const FlowCase& c, const PoreCluster& pc, const char* what) {
  if (pc.spanning == 0)
    throw ComputationError(fmt::format("{}: no fluid cluster spans the {} along {} ({} fluid {} in {} clusters): "
                                       "nothing can flow",
                                       c.file, c.format == "xyz" ? "packing" : "image", axis_name(c.axis),
                                       pc.fluid_voxels, what, pc.components));
}

// The lattice of voxels x M^3 nodes must fit what is built from it: refine_mask's 2^40 nodes
// for an image (labelled as voxels), the labelling's 2^31 - 2 for a packing (labelled as
// nodes). Said for the option before anything is allocated.
void check_lattice_size(const std::string& file, std::array<int, 3> voxels, int M, double limit, const char* what) {
  const double nodes = static_cast<double>(voxels[0]) * voxels[1] * voxels[2] * M * M * M;
  if (nodes > limit)
    throw UsageError(fmt::format("--refine: {} x {} x {} voxels of {} at M = {} make {:.3g} lattice nodes, more than {}",
                                 voxels[0], voxels[1], voxels[2], file, M, nodes, what));
}

}  // namespace

double default_tau(const FlowCase& c) { return c.interpolated_walls ? 1.0 : 0.55; }

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

FlowCase image_case(const FlowImage& image, int M, int axis, bool periodic_axis) {
  FlowCase c;
  c.file = image.file;
  c.format = image.format;
  c.title = image.title;
  c.voxels = image.dims;
  c.refine = M;
  c.axis = axis;
  check_lattice_size(image.file, image.dims, M, 1099511627776.0, "2^40");
  std::tie(c.node_origin, c.node_spacing) = refined_geometry(image.origin, image.spacing, M);
  c.delta = image.delta;
  c.d0 = image.d0;
  c.scale = image.scale;
  const double voxels = static_cast<double>(image.size());
  c.porosity_voxels = static_cast<double>(image.fluid_voxels()) / voxels;
  c.porosity = image.porosity.value_or(c.porosity_voxels);
  c.porosity_source = image.porosity ? "file" : "voxels";
  auto pc = percolating_cluster(image.fluid, image.dims, axis, periodic_axis);
  require_cluster(c, pc, "voxels");
  const long m3 = 1L * M * M * M;
  c.nodes = static_cast<long>(image.size()) * m3;
  c.cluster_nodes = pc.cluster_voxels * m3;
  c.dropped_pockets = pc.dropped_components;
  c.dropped_nodes = pc.dropped_voxels * m3;
  c.cluster = std::move(pc.fluid);
  return c;
}

void FlowCase::make_lattice() {
  if (!lattice.fluid.empty()) return;
  lattice.nx = voxels[0] * refine;
  lattice.ny = voxels[1] * refine;
  lattice.nz = voxels[2] * refine;
  lattice.fluid = refine_mask(cluster, voxels, refine);
}

void FlowCase::release_lattice() {
  if (format == "xyz") return;  // built from the spheres once; nothing to rebuild it from
  lattice = lbm::PoreLattice{};
}

FlowCase sphere_case(const packing::Packing& p, double delta, int M, int axis, bool periodic_axis) {
  if (!(p.periodic[0] && p.periodic[1] && p.periodic[2]))
    throw InputError(p.file, 0, "the sphere packing must be periodic on every axis (pbc=\"T T T\") for the flow");
  if (delta * p.d0 > p.box.minCoeff())
    throw UsageError(fmt::format("{}: --delta {} is larger than the box (smallest side {:.4g} D0)", p.file, delta,
                                 p.box.minCoeff() / p.d0));
  FlowCase c;
  c.file = p.file;
  c.format = "xyz";
  c.refine = M;
  c.axis = axis;
  const auto grid = voxel::make_grid(p.box, delta * p.d0, {true, true, true});
  c.voxels = grid.dims;
  check_lattice_size(p.file, grid.dims, M, 2147483646.0, "2^31 - 2 (the labelling of the pore space)");
  std::tie(c.node_origin, c.node_spacing) = refined_geometry(0.5 * grid.spacing, grid.spacing, M);
  c.delta = delta;
  c.d0 = p.d0;
  c.scale = p.scale;
  const auto volumes = voxel::sphere_volumes(p.centres, p.radii, p.box, p.periodic);
  c.porosity = 1 - (volumes.total - volumes.pair_overlap) / p.box.prod();
  c.porosity_source = "sphere_pair_lenses";
  // Node coordinates: node i sits at (i + 1/2) h; a sphere of radius r spans r / h nodes (h
  // the geometric mean of the three sides, which differ only by the rounding of L / delta).
  const Eigen::Vector3d h = c.node_spacing;
  const double h_mean = std::cbrt(h.prod());
  std::vector<lbm::LatticeSphere> spheres;
  for (Eigen::Index s = 0; s < p.centres.rows(); ++s)
    spheres.push_back({p.centres(s, 0) / h[0] - 0.5, p.centres(s, 1) / h[1] - 0.5, p.centres(s, 2) / h[2] - 0.5,
                       p.radii[s] / h_mean});
  c.lattice = lbm::periodic_spheres(grid.dims[0] * M, grid.dims[1] * M, grid.dims[2] * M, spheres);
  const std::array<int, 3> n{c.lattice.nx, c.lattice.ny, c.lattice.nz};
  auto pc = percolating_cluster(c.lattice.fluid, n, axis, periodic_axis);
  c.porosity_voxels = static_cast<double>(pc.fluid_voxels) / static_cast<double>(c.lattice.nodes());
  require_cluster(c, pc, "nodes");
  c.nodes = c.lattice.nodes();
  c.cluster_nodes = pc.cluster_voxels;
  c.dropped_pockets = pc.dropped_components;
  c.dropped_nodes = pc.dropped_voxels;
  c.lattice.fluid = std::move(pc.fluid);
  c.interpolated_walls = true;
  return c;
}

RefinementCases read_flow_cases(const std::string& path, const InputOptions& o, const std::vector<int>& refinements) {
  RefinementCases r;
  // One case per M from one reading; a coarse M at which nothing spans is skipped (said), the
  // finest is the run's own and throws.
  const auto each = [&](const auto& make) {
    for (std::size_t k = 0; k < refinements.size(); ++k) try {
        r.cases.push_back(make(refinements[k]));
      } catch (const ComputationError& e) {
        if (k + 1 == refinements.size()) throw;
        r.skipped.push_back(fmt::format("M = {} skipped: {}", refinements[k], e.what()));
      }
  };
  if (!o.dims.empty()) {
    const FlowImage image = read_raw_image(path, parse_dims(o.dims));
    each([&](int M) { return image_case(image, M, o.axis, o.periodic_axis); });
    return r;
  }
  // The format from the content, for a file and for standard input alike (docs/formats.md).
  io::Input input(path);
  const auto format = input.format();
  if (format == io::InputFormat::vtk) {
    const FlowImage image = read_vtk_image(input);
    each([&](int M) { return image_case(image, M, o.axis, o.periodic_axis); });
    return r;
  }
  if (format == io::InputFormat::xyz) {
    if (!(o.delta > 0))
      throw UsageError(path + ": a sphere packing needs --delta (the voxel side in D0; the node side is delta/M)");
    auto packings = packing::read_packings(input, {o.scale, o.d0});
    if (packings.size() != 1) throw InputError(path, 0, "holds several frames: give lbflow one packing per file");
    each([&](int M) { return sphere_case(packings.front(), o.delta, M, o.axis, o.periodic_axis); });
    return r;
  }
  input.fail_format("a VTK image (STRUCTURED_POINTS), a sphere packing (extended XYZ), or raw bytes with --dims");
}

FlowCase read_flow_case(const std::string& path, const InputOptions& o) {
  return std::move(read_flow_cases(path, o, {o.refine}).cases.front());
}

}  // namespace cmp::flowrun
