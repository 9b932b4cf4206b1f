#include "shellbench/mechanics_benchmarks.hpp"

#include "shellbench/buckling_run.hpp"
#include "shellbench/flat_sheets.hpp"
#include "shellbench/membrane_squeeze.hpp"
#include "shellbench/sphere_inflation.hpp"

#include "core/errors.hpp"
#include "core/registry.hpp"
#include "elasticity/clamped_plate.hpp"
#include "io/csv.hpp"
#include "spheremesh/annealing.hpp"
#include "spheremesh/spherical_delaunay.hpp"
#include "spheremesh/subdivision.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace cmp::shellbench {

using namespace cmp::shell;

namespace {

// The "# key=value" lines every shell case starts with: provenance, what the case is, and the
// shell's radius and material.
void write_case_meta(io::CsvWriter& csv, const std::string& provenance, const std::string& what, double radius,
                     const MaterialParameters& m) {
  csv.meta("provenance", provenance);
  csv.meta("case", what);
  csv.meta("R0", io::format_number(radius));
  csv.meta("E", io::format_number(m.youngs_modulus));
  csv.meta("nu", io::format_number(m.poisson_ratio));
  csv.meta("t", io::format_number(m.thickness));
}

using io::format_number;

void write_sphere(bool quick, std::ostream& out, const std::string& provenance,
                  const std::function<void(const std::string&)>& note) {
  SphereInflationCase c;
  if (quick) {
    c.loads = {1e-4, 1e-3, 1e-2};
  } else {
    c.loads = {1e-4, 2e-4, 5e-4, 1e-3, 1.5e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 7e-3, 8e-3, 9e-3, 1e-2};
  }
  if (note) note(fmt::format("sphere: icosahedral level {}, {} loads, {} models", c.level, c.loads.size(), c.models.size()));
  const auto rows = sphere_inflation(c);
  io::CsvWriter csv(out);
  write_case_meta(csv, provenance, "sphere (B.5.1, Fig. B.4A): strain eps_r = cbrt(V/V0) - 1 of an inflated sphere",
                  c.radius, c.material);
  csv.meta("level", std::to_string(c.level));
  csv.meta("columns", "dP_E = dP/E; eps_r of the mesh; eps_r_svk the SVK sphere (corrected B.81); eps_r_printed the "
                      "printed B.82; eps_r_linear the small-strain limit; rel_error = eps_r/eps_r_svk - 1");
  csv.header({"model", "dP_E", "eps_r", "eps_r_svk", "eps_r_printed", "eps_r_linear", "rel_error", "iterations",
              "residual"});
  for (const auto& r : rows)
    csv.row({r.model, format_number(r.load), format_number(r.strain), format_number(r.strain_corrected),
             format_number(r.strain_printed), format_number(r.strain_linear),
             format_number(r.strain / r.strain_corrected - 1), std::to_string(r.relax.iterations),
             format_number(r.relax.residual)});
}

void write_plates_contact(bool quick, std::ostream& out, const std::string& provenance,
                          const std::function<void(const std::string&)>& note) {
  MembraneSqueezeCase c;
  if (quick) {
    c.level = 4;
    c.compressions = {0.05, 0.1, 0.2};
  } else {
    c.compressions = {0.01, 0.02, 0.04, 0.06, 0.08, 0.1, 0.125, 0.15, 0.175, 0.2, 0.25, 0.3, 0.35, 0.4};
  }
  if (note) note(fmt::format("plates-contact: icosahedral level {}, {} compressions", c.level, c.compressions.size()));
  const auto rows = membrane_squeeze(c);
  io::CsvWriter csv(out);
  write_case_meta(csv, provenance,
                  "plates-contact (B.6, Fig. B.9): inflated SVK membrane, constant volume, between rigid plates",
                  c.radius, c.material);
  csv.meta("P_i_E", format_number(c.inflation));
  csv.meta("vertex_radius", format_number(c.vertex_radius));
  csv.meta("level", std::to_string(c.level));
  csv.meta("columns", "X = 1 - eta/R_i (eta = gap/2 - R_v); F_hat = F/(E t R0) per plate; "
                      "P_P0 = P/P_i; *_theory from the shooting solution");
  csv.header({"X", "gap", "F_hat", "F_hat_theory", "P_P0", "P_P0_theory", "contact_radius_theory_R0", "volume_error",
              "iterations", "volume_updates", "residual"});
  for (const auto& r : rows)
    csv.row({format_number(r.compression), format_number(r.gap), format_number(r.force), format_number(r.force_theory),
             format_number(r.pressure), format_number(r.pressure_theory), format_number(r.contact_radius_theory),
             format_number(r.volume_error), std::to_string(r.relax.iterations), std::to_string(r.relax.volume_updates),
             format_number(r.relax.residual)});
}

void write_poisson(bool quick, std::ostream& out, const std::string& provenance,
                   const std::function<void(const std::string&)>& note) {
  const std::vector<double> nus = quick ? std::vector<double>{0.1, 0.3, 0.45}
                                        : std::vector<double>{0.1, 0.15, 0.2, 0.25, 0.3, 1.0 / 3.0, 0.35, 0.4, 0.45, 0.5};
  const long vertices = quick ? 600 : 2200;
  const double side = 2.28, E = 25e6, t = 0.1;
  if (note) note(fmt::format("poisson: {}-vertex sheet, {} values of nu", vertices, nus.size()));
  const auto rows = poisson_ratios({"svk", "springs-kot", "springs-van-gelder"}, nus, side, vertices, E, t);
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("case", "poisson (B.5.2, Fig. B.4B): square sheet pulled by uniform edge tractions 1e-3 E t");
  csv.meta("L", format_number(side));
  csv.meta("E", format_number(E));
  csv.meta("t", format_number(t));
  csv.meta("vertices", std::to_string(vertices));
  csv.meta("columns", "nu_input the material's nu; nu_measured = -eps_y/eps_x of the sheet; strain_x = eps_x");
  csv.header({"model", "nu_input", "nu_measured", "strain_x", "iterations", "residual"});
  for (const auto& r : rows)
    csv.row({r.model, format_number(r.nu_input), format_number(r.nu_measured), format_number(r.strain_x),
             std::to_string(r.relax.iterations), format_number(r.relax.residual)});
}

// The clamped plates share their models: bending with the calibrated hinges, with the local
// hinges, and the membrane alone.
struct PlateModel {
  const char* name;
  const char* bending;
};
const PlateModel kPlateModels[] = {{"svk+hinge-uniform", "hinge-uniform"}, {"svk+hinge", "hinge"}, {"svk", ""}};

void plate_meta(io::CsvWriter& csv, const std::string& provenance, const PlateCase& c, const std::string& what) {
  write_case_meta(csv, provenance, what, c.radius, c.material);
  csv.meta("vertices", std::to_string(c.vertices));
  csv.meta("clamping", "the rim and every vertex within one lattice spacing of it fixed");
}

void write_plate_profile(bool point, bool quick, std::ostream& out, const std::string& provenance,
                         const std::function<void(const std::string&)>& note) {
  PlateCase c;
  if (quick) c.vertices = 600;
  c.relative_tolerance = 1e-11;
  const elasticity::Sheet sheet{c.material.youngs_modulus, c.material.poisson_ratio, c.material.thickness};
  // The thesis's loads: P0 = 5e3 N (w_max = 2.15 t: far outside the linear theory) and the
  // total 1e3 N spread uniformly (w_max = 0.107 t). Also a point load inside the linear regime
  // (w_max = t/20), where the linear theory applies.
  std::vector<std::pair<std::string, double>> loads;
  if (point) {
    loads = {{"linear", 0.1 * elasticity::point_load_linear_limit(sheet, c.radius)}, {"thesis", 5e3}};
  } else {
    loads = {{"thesis", 1e3 / (std::numbers::pi * c.radius * c.radius)}};
  }
  io::CsvWriter csv(out);
  plate_meta(csv, provenance, c,
             point ? "plate-point (B.5.3, Fig. B.5): clamped disc, central point load P0 [N]"
                   : "plate-uniform (B.5.3, Fig. B.6): clamped disc, uniform load q [Pa] (total 1e3 N)");
  csv.meta("columns", "r_R0 = r/R0; w_t = w/t of the mesh at every free vertex; w_t_theory the linear plate "
                      "(B.84 or B.86) at the same r");
  csv.header({"model", "load", "load_value", "r_R0", "w_t", "w_t_theory", "iterations", "residual"});
  for (const auto& m : kPlateModels) {
    c.bending = m.bending;
    for (const auto& [label, value] : loads) {
      if (note) note(fmt::format("{}: {} load {} on {} vertices", m.name, label, value, c.vertices));
      const auto res = clamped_plate(c, {PlateLoad{point, value}}).front();
      std::vector<std::size_t> order(res.r.size());
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
      std::sort(order.begin(), order.end(), [&](auto a, auto b) { return res.r[a] < res.r[b]; });
      for (auto k : order) {
        const double r = res.r[k];
        const double w = point ? elasticity::point_load_deflection(sheet, c.radius, value, r)
                               : elasticity::uniform_load_deflection(sheet, c.radius, value, r);
        csv.row({m.name, label, format_number(value), format_number(r / c.radius),
                 format_number(res.w[k] / c.material.thickness), format_number(w / c.material.thickness),
                 std::to_string(res.relax.iterations), format_number(res.relax.residual)});
      }
    }
  }
}

void write_plate_point(bool quick, std::ostream& out, const std::string& provenance,
                       const std::function<void(const std::string&)>& note) {
  write_plate_profile(true, quick, out, provenance, note);
}
void write_plate_uniform(bool quick, std::ostream& out, const std::string& provenance,
                         const std::function<void(const std::string&)>& note) {
  write_plate_profile(false, quick, out, provenance, note);
}

void write_plate_large(bool quick, std::ostream& out, const std::string& provenance,
                       const std::function<void(const std::string&)>& note) {
  PlateCase c;
  c.radius = 2.14;
  c.vertices = quick ? 500 : 1000;
  c.material = {25e6, 0.0, 0.1};
  c.relative_tolerance = 1e-11;
  const elasticity::Sheet sheet{c.material.youngs_modulus, c.material.poisson_ratio, c.material.thickness};
  const std::vector<double> stars = quick ? std::vector<double>{0.1, 10, 1000}
                                          : std::vector<double>{0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000};
  std::vector<PlateLoad> loads;
  for (double p : stars) loads.push_back({false, elasticity::plate_pressure_from_star(sheet, c.radius, p)});
  io::CsvWriter csv(out);
  plate_meta(csv, provenance, c, "plate-large (B.5.4, Fig. B.7): clamped disc, uniform load, large deflection");
  csv.meta("columns", "P_star = (q/E)(R0/t)^4; w_max_t = w_max/t of the mesh; w_max_t_theory from B.88/B.89");
  csv.header({"model", "P_star", "w_max_t", "w_max_t_theory", "iterations", "residual"});
  for (const auto& m : kPlateModels) {
    c.bending = m.bending;
    if (note) note(fmt::format("plate-large: {} on {} vertices, {} loads", m.name, c.vertices, loads.size()));
    const auto res = clamped_plate(c, loads);
    for (std::size_t k = 0; k < res.size(); ++k)
      csv.row({m.name, format_number(stars[k]), format_number(res[k].w_max / c.material.thickness),
               format_number(elasticity::large_deflection_max_deflection(c.material.poisson_ratio, stars[k])),
               std::to_string(res[k].relax.iterations), format_number(res[k].relax.residual)});
  }
}

// One mesh of the buckling case: a label (the CSV's model column), the annealing's T_end
// (NaN for the subdivision mesh) and the mesh on the unit sphere.
struct BucklingMesh {
  std::string label;
  double t_end;
  mesh::TriMesh rest;
};

// N points annealed from T_max = 1000 down to T_end (A.2.2), triangulated.
BucklingMesh annealed_mesh(int points, double t_end, int anneals, int sweeps) {
  spheremesh::AnnealingParameters a;
  a.points = points;
  a.t_min = t_end;
  a.anneals = anneals;
  a.sweeps_per_anneal = sweeps;
  const auto r = spheremesh::anneal_on_sphere(a);
  return {fmt::format("rndmesh-T{:g}", t_end), t_end, {r.points, spheremesh::spherical_delaunay(r.points)}};
}

// The buckling series: the thesis's springs on every mesh, and the SVK membrane (with the same
// hinges) on some, whose stress stays uniform on unequal triangles (see buckling_run.hpp).
struct BucklingSeries {
  std::size_t mesh;
  const char* stretching;
};

void write_buckling(bool quick, std::ostream& out, const std::string& provenance,
                    const std::function<void(const std::string&)>& note) {
  const std::vector<double> gammas = quick ? std::vector<double>{1e3, 1e4} : std::vector<double>{1e3, 5e3, 1e4, 5e4};
  const int level = 4;
  const int points = quick ? 642 : 1000;
  const std::vector<double> t_ends = quick ? std::vector<double>{200} : std::vector<double>{0.1, 10, 50, 200};
  const int anneals = quick ? 50 : 200, sweeps = quick ? 20 : 100;
  std::vector<BucklingMesh> meshes;
  meshes.push_back({fmt::format("icosa-L{}", level), std::nan(""),
                    spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, 1.0)});
  for (double t : t_ends) {
    if (note) note(fmt::format("buckling: annealing {} points to T_end = {:g}", points, t));
    meshes.push_back(annealed_mesh(points, t, anneals, sweeps));
  }
  std::vector<BucklingSeries> series;
  for (std::size_t k = 0; k < meshes.size(); ++k) series.push_back({k, "springs-seung-nelson"});
  if (!quick)
    for (std::size_t k : {std::size_t{0}, std::size_t{1}, meshes.size() - 1}) series.push_back({k, "svk"});
  BucklingCase c;
  io::CsvWriter csv(out);
  csv.meta("provenance", provenance);
  csv.meta("case", "buckling (B.7, Fig. B.10): sphere under growing external pressure, buckling pressure / p_c");
  csv.meta("shell", "bending " + c.bending + ", stretching springs-seung-nelson (the thesis's) or svk; E = 1, R0 = 1, "
                    "nu = 1/3, t from gamma");
  csv.meta("annealing", fmt::format("{} points, T_max = 1000, {} anneals of {} sweeps, seed 1", points, anneals, sweeps));
  csv.meta("protocol", fmt::format("p/p_c raised in steps of {:g} from the last stable state, bracket halved to {:g}; "
                                   "buckled when V drops {:g} below the last stable V; kick {:g} t per relaxation, "
                                   "seed {}",
                                   c.step, c.resolution, c.volume_drop, c.kick, c.seed));
  csv.meta("columns", "model = mesh (icosa-L<level> or rndmesh-T<T_end>), -svk for the SVK membrane; p_pc = first "
                      "buckled p/p_c; p_pc_stable = last stable p/p_c; p_pc_theory = 1; V_V0 and dr_t = rms radial "
                      "deviation / t at p_pc_stable");
  csv.header({"model", "stretching", "T_end", "vertices", "gamma", "p_pc", "p_pc_stable", "p_pc_theory", "V_V0",
              "dr_t", "R0_t", "relaxations", "iterations", "unconverged", "nonfinite"});
  for (const auto& [k, stretching] : series) {
    const BucklingMesh& m = meshes[k];
    const std::string label = m.label + (std::string(stretching) == "svk" ? "-svk" : "");
    c.stretching = stretching;
    for (double g : gammas) {
      c.gamma = g;
      const auto r = buckling_run(m.rest, c);
      if (note) note(fmt::format("buckling: {} gamma {:g}: p/p_c = {:.4f}", label, g, r.pressure));
      csv.row({label, stretching, std::isnan(m.t_end) ? "" : format_number(m.t_end), std::to_string(m.rest.V.rows()),
               format_number(g), r.buckled ? format_number(r.pressure) : "", format_number(r.stable_pressure), "1",
               format_number(r.stable_volume), format_number(r.stable_roughness), format_number(1.0 / r.thickness),
               std::to_string(r.relaxations), std::to_string(r.iterations), std::to_string(r.unconverged), std::to_string(r.nonfinite)});
    }
  }
}

struct Case {
  const char* name;
  void (*run)(bool, std::ostream&, const std::string&, const std::function<void(const std::string&)>&);
};

const Case kCases[] = {
    {"sphere", &write_sphere},
    {"poisson", &write_poisson},
    {"plate-point", &write_plate_point},
    {"plate-uniform", &write_plate_uniform},
    {"plate-large", &write_plate_large},
    {"plates-contact", &write_plates_contact},
    {"buckling", &write_buckling},
};

}  // namespace

std::vector<std::string> mechanics_benchmark_names() {
  std::vector<std::string> names;
  for (const auto& c : kCases) names.push_back(c.name);
  return names;
}

void check_mechanics_benchmark(const std::string& name) { find_style(kCases, name, "benchmark"); }

void run_mechanics_benchmark(const std::string& name, bool quick, std::ostream& out, const std::string& provenance,
                             const std::function<void(const std::string&)>& note) {
  find_style(kCases, name, "benchmark").run(quick, out, provenance, note);
}

}  // namespace cmp::shellbench
