// Palabos 1.5 (Debian libplb-dev, the lattice Boltzmann engine the thesis used) beside
// lbflow's kernel, for make bench. Built only when CMake finds Palabos and MPI (the Debian
// library is built with MPI: run it under `mpirun -np P`; each rank is one core).
//   bench_palabos speed N STEPS [mrt]        Palabos D3Q19 MRT, BGK (and TRT on the porous box)
//                                            on the dense N^3 periodic box (Guo body force; MRT
//                                            also with pressure planes, no force term) and
//                                            on bench_lbm's porous N^3 box (the same random
//                                            spheres, pressure planes): MLUPS over fluid nodes;
//                                            `mrt`: the MRT runs only
//   bench_palabos cluster FILE M STEPS       the same for the lattice lbflow builds from an
//                                            image (its percolating cluster, refined M times),
//                                            pressure planes along x, MRT
//   bench_palabos lbflow-cluster FILE M THREADS STEPS
//                                            lbflow's FlowSolver (mrt) on that same lattice
//   bench_palabos poiseuille                 same physics? kappa of a square duct from Palabos
//                                            and from lbflow (body force, tau = 1 and 1.5;
//                                            pressure planes, tau = 1)
// Each prints CSV with a header line (rank 0 only). Timings: best of 3 runs of STEPS steps
// after 2 warm-up steps, between MPI barriers; Palabos's internal statistics (averages it
// gathers every step) are off, solid nodes are BounceBack cells of the dense block lattice (Palabos
// updates every node), MLUPS = fluid nodes x steps / seconds for both codes.
#include "flowrun/flow_case.hpp"
#include "lbm/flow_solver.hpp"
#include "lbm/pore_lattice.hpp"
#include "lbm/sphere_lattice.hpp"
#include "lbm/steady_state.hpp"

#include "core/random.hpp"

// Palabos's templates: palabos3D.hh minus multiGrid (whose coarseGridProcessors3D.hh calls a
// vector::assign overload that does not exist, which GCC 12 rejects) and the 2D parts.
#include "palabos3D.h"
#include <parallelism/headers3D.hh>
#include <latticeBoltzmann/headers3D.hh>
#include <core/headers3D.hh>
#include <basicDynamics/headers3D.hh>
#include <boundaryCondition/headers3D.hh>
#include <complexDynamics/headers3D.hh>
#include <io/headers3D.hh>
#include <atomicBlock/headers3D.hh>
#include <multiBlock/headers3D.hh>
#include <algorithm/headers3D.hh>
#include <dataProcessors/headers3D.hh>
#include <coProcessors/headers3D.hh>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using T = double;
using cmp::lbm::PoreLattice;

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
bool main_rank() { return plb::global::mpi().isMainProcessor(); }

// Makes every solid node of `pore` (absolute coordinates) a full bounce-back cell, on
// whichever block of whichever rank holds it.
template <template <typename U> class D>
struct SolidToBounceBack : public plb::BoxProcessingFunctional3D_L<T, D> {
  explicit SolidToBounceBack(const PoreLattice* pore) : pore_(pore) {}
  void process(plb::Box3D box, plb::BlockLattice3D<T, D>& lattice) override {
    const plb::Dot3D at = lattice.getLocation();
    for (plb::plint x = box.x0; x <= box.x1; ++x)
      for (plb::plint y = box.y0; y <= box.y1; ++y)
        for (plb::plint z = box.z0; z <= box.z1; ++z)
          if (!pore_->fluid[pore_->index(x + at.x, y + at.y, z + at.z)])
            lattice.attributeDynamics(x, y, z, new plb::BounceBack<T, D>(1.));
  }
  SolidToBounceBack* clone() const override { return new SolidToBounceBack(*this); }
  void getTypeOfModification(std::vector<plb::modif::ModifT>& m) const override { m[0] = plb::modif::dataStructure; }

 private:
  const PoreLattice* pore_;
};

// A Palabos lattice on `pore` with bulk dynamics `bulk` (owned by the lattice). Driving:
// pressure = Zou & He density nodes on the first and last x planes (rho = 1 +- drop/2,
// periodic y and z, as lbflow's pressure driving), else a Guo body force g along x in a
// fully periodic box (descriptors with a force field only).
template <template <typename U> class D>
struct PalabosRun {
  plb::MultiBlockLattice3D<T, D> lattice;

  PalabosRun(const PoreLattice& pore, plb::Dynamics<T, D>* bulk, bool pressure, double drive)
      : lattice(pore.nx, pore.ny, pore.nz, bulk) {
    using namespace plb;
    lattice.toggleInternalStatistics(false);
    lattice.periodicity().toggleAll(true);
    const Box3D all = lattice.getBoundingBox();
    const Box3D in(0, 0, 0, pore.ny - 1, 0, pore.nz - 1), out(pore.nx - 1, pore.nx - 1, 0, pore.ny - 1, 0, pore.nz - 1);
    if (pressure) {
      lattice.periodicity().toggle(0, false);
      OnLatticeBoundaryCondition3D<T, D>* bc = createZouHeBoundaryCondition3D<T, D>();
      bc->addPressureBoundary0N(in, lattice);
      bc->addPressureBoundary0P(out, lattice);
      delete bc;
    }
    applyProcessingFunctional(new SolidToBounceBack<D>(&pore), all, lattice);
    initializeAtEquilibrium(lattice, all, 1., Array<T, 3>(0., 0., 0.));
    if (pressure) {
      setBoundaryDensity(lattice, in, 1 + drive / 2);
      setBoundaryDensity(lattice, out, 1 - drive / 2);
      initializeAtEquilibrium(lattice, in, 1 + drive / 2, Array<T, 3>(0., 0., 0.));
      initializeAtEquilibrium(lattice, out, 1 - drive / 2, Array<T, 3>(0., 0., 0.));
    } else if constexpr (D<T>::ExternalField::sizeOfForce == 3) {
      setExternalVector(lattice, all, D<T>::ExternalField::forceBeginsAt, Array<T, 3>(drive, 0., 0.));
    }
    lattice.initialize();
  }

  void step(long n) {
    for (long i = 0; i < n; ++i) lattice.collideAndStream();
  }
  // Best wall time of 3 runs of `steps` steps (after 2 warm-up steps), between barriers.
  double best_seconds(long steps) {
    step(2);
    double best = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
      plb::global::mpi().barrier();
      const double t0 = now();
      step(steps);
      plb::global::mpi().barrier();
      best = std::min(best, now() - t0);
    }
    return best;
  }
  // Superficial mean of u_x over the whole box (bounce-back cells report zero velocity).
  double mean_ux() { return plb::computeAverage(*plb::computeVelocityComponent(lattice, lattice.getBoundingBox(), 0)); }
};

template <template <typename U> class D>
void speed_row(const char* what, const PoreLattice& pore, const char* collision, plb::Dynamics<T, D>* bulk, bool pressure,
               long steps) {
  PalabosRun<D> run(pore, bulk, pressure, pressure ? 1e-3 : 1e-6);
  const double s = run.best_seconds(steps);
  const long fluid = pore.fluid_count();
  if (main_rank())
    std::printf("%s,%d,%.4f,%d,%s,%s,%ld,%ld,%.4f,%.2f,%.2f,%d\n", what, pore.nx, pore.porosity(), plb::global::mpi().getSize(),
                collision, pressure ? "pressure" : "body_force", fluid, steps, s, fluid * double(steps) / s / 1e6,
                pore.nodes() * double(steps) / s / 1e6, static_cast<int>(sizeof(plb::Cell<T, D>)));
  std::fflush(stdout);
}

const char* kSpeedHeader =
    "case,N,porosity,processes,collision,driving,fluid_nodes,steps,seconds,mlups,mlups_all_nodes,bytes_per_node\n";

int speed(int n, long steps, bool mrt_only) {
  using namespace plb;
  using namespace plb::descriptors;
  if (main_rank()) std::printf("%s", kSpeedHeader);
  const PoreLattice dense = cmp::lbm::open_box(n, n, n);
  speed_row<ForcedMRTD3Q19Descriptor>("dense", dense, "mrt", new GuoExternalForceMRTdynamics<T, ForcedMRTD3Q19Descriptor>(1.), false, steps);
  if (!mrt_only)
    speed_row<ForcedD3Q19Descriptor>("dense", dense, "bgk", new GuoExternalForceBGKdynamics<T, ForcedD3Q19Descriptor>(1.), false, steps);
  speed_row<MRTD3Q19Descriptor>("dense", dense, "mrt", new MRTdynamics<T, MRTD3Q19Descriptor>(1.), true, steps);
  const PoreLattice porous = cmp::lbm::random_sphere_box(n, 0.35, 2026);
  speed_row<MRTD3Q19Descriptor>("porous", porous, "mrt", new MRTdynamics<T, MRTD3Q19Descriptor>(1.), true, steps);
  if (mrt_only) return 0;
  speed_row<D3Q19Descriptor>("porous", porous, "bgk", new BGKdynamics<T, D3Q19Descriptor>(1.), true, steps);
  speed_row<D3Q19Descriptor>("porous", porous, "trt", new TRTdynamics<T, D3Q19Descriptor>(1.), true, steps);
  return 0;
}

PoreLattice cluster_lattice(const std::string& file, int M) {
  cmp::flowrun::InputOptions opt;
  opt.refine = M;
  cmp::flowrun::FlowCase c = cmp::flowrun::read_flow_case(file, opt);
  c.make_lattice();
  c.lattice.wall_fraction = nullptr;
  return c.lattice;
}

int cluster(const std::string& file, int M, long steps) {
  using namespace plb;
  using namespace plb::descriptors;
  if (main_rank()) std::printf("%s", kSpeedHeader);
  const PoreLattice pore = cluster_lattice(file, M);
  speed_row<MRTD3Q19Descriptor>("cluster", pore, "mrt", new MRTdynamics<T, MRTD3Q19Descriptor>(1.), true, steps);
  return 0;
}

int lbflow_cluster(const std::string& file, int M, int threads, long steps) {
  const PoreLattice pore = cluster_lattice(file, M);
  cmp::lbm::FlowSettings s;  // mrt, pressure driving, drop 1e-3: lbflow's defaults
  omp_set_num_threads(threads);
  cmp::lbm::FlowSolver solver(pore, s);
  solver.step(2);
  double best = 1e30;
  for (int rep = 0; rep < 3; ++rep) {
    const double t0 = now();
    solver.step(steps);
    best = std::min(best, now() - t0);
  }
  std::printf("case,N,porosity,threads,collision,driving,fluid_nodes,steps,seconds,mlups,bytes_per_node\n");
  std::printf("cluster,%d,%.4f,%d,mrt,pressure,%ld,%ld,%.4f,%.2f,%.1f\n", pore.nx, pore.porosity(), threads,
              solver.fluid_nodes(), steps, best, solver.fluid_nodes() * double(steps) / best / 1e6,
              solver.bytes_per_fluid_node());
  return 0;
}

// Palabos's kappa of `pore` (as lbflow defines it: nu <u_x>_box / |grad p|) driven by a body
// force g = 1e-6 along x in a fully periodic box, or (pressure) by a density drop of 1e-3
// between the first and last x planes, after enough steps that kappa changes by less than
// 1e-9 relative over 500 steps.
template <template <typename U> class D>
double palabos_kappa(const PoreLattice& pore, plb::Dynamics<T, D>* bulk, double tau, bool pressure = false) {
  const double drive = pressure ? 1e-3 : 1e-6, nu = (tau - 0.5) / 3;
  const double grad_p = pressure ? drive / 3 / (pore.nx - 1) : drive;
  PalabosRun<D> run(pore, bulk, pressure, drive);
  double kappa = 0, last = -1;
  for (int k = 0; k < 400 && std::abs(kappa - last) > 1e-9 * std::abs(kappa); ++k) {
    last = kappa;
    run.step(500);
    kappa = nu * run.mean_ux() / grad_p;
  }
  return kappa;
}

double lbflow_kappa(const PoreLattice& pore, const std::string& collision, double tau, bool pressure = false) {
  cmp::lbm::FlowSettings s;
  s.collision = collision;
  s.collision_parameters.tau = tau;
  s.driving = pressure ? cmp::lbm::Driving::kPressure : cmp::lbm::Driving::kBodyForce;
  return cmp::lbm::solve_steady(pore, s, {1e-10, 500, 1, 400000}).final.kappa_lu;
}

int poiseuille() {
  using namespace plb;
  using namespace plb::descriptors;
  const int w = 12;
  const PoreLattice duct = cmp::lbm::channel(4, w, 0, 1, true, w);  // 4 x 14 x 14 nodes, w x w fluid
  std::printf("case,width,tau,palabos_mrt,lbflow_mrt_dh,lbflow_mrt,palabos_bgk,lbflow_bgk\n");
  for (double tau : {1.0, 1.5}) {
    const double kp_mrt = palabos_kappa<ForcedMRTD3Q19Descriptor>(
        duct, new GuoExternalForceMRTdynamics<T, ForcedMRTD3Q19Descriptor>(1 / tau), tau);
    const double kp_bgk = palabos_kappa<ForcedD3Q19Descriptor>(
        duct, new GuoExternalForceBGKdynamics<T, ForcedD3Q19Descriptor>(1 / tau), tau);
    std::printf("square_duct,%d,%.2f,%.15g,%.15g,%.15g,%.15g,%.15g\n", w, tau, kp_mrt, lbflow_kappa(duct, "mrt-dh", tau),
                lbflow_kappa(duct, "mrt", tau), kp_bgk, lbflow_kappa(duct, "bgk", tau));
    std::fflush(stdout);
  }
  // Pressure planes (Zou & He in both), MRT with the same rates, a longer duct.
  const PoreLattice long_duct = cmp::lbm::channel(16, w, 0, 1, true, w);
  const double kp = palabos_kappa<MRTD3Q19Descriptor>(long_duct, new MRTdynamics<T, MRTD3Q19Descriptor>(1.), 1., true);
  std::printf("square_duct_pressure_16,%d,1.00,%.15g,%.15g,%.15g,,\n", w, kp, lbflow_kappa(long_duct, "mrt-dh", 1., true),
              lbflow_kappa(long_duct, "mrt", 1., true));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  plb::plbInit(&argc, &argv);
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "speed" && (argc == 4 || (argc == 5 && std::string(argv[4]) == "mrt")))
      return speed(std::atoi(argv[2]), std::atol(argv[3]), argc == 5);
    if (mode == "cluster" && argc == 5) return cluster(argv[2], std::atoi(argv[3]), std::atol(argv[4]));
    if (mode == "lbflow-cluster" && argc == 6)
      return lbflow_cluster(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atol(argv[5]));
    if (mode == "poiseuille" && argc == 2) return poiseuille();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_palabos: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: bench_palabos speed N STEPS [mrt] | cluster FILE M STEPS | lbflow-cluster FILE M THREADS STEPS | poiseuille\n");
  return 2;
}
