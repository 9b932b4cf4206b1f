#include "packrun/packing_analysis.hpp"

#include "core/errors.hpp"
#include "core/minimum_image.hpp"
#include "shell/voronoi_faces.hpp"
#include "io/csv.hpp"
#include "packing/shell_volumes.hpp"

#include <fmt/format.h>

#include <cmath>

namespace cmp::packrun {

namespace {

bool all_periodic(const std::array<bool, 3>& p) { return p[0] && p[1] && p[2]; }

// The shell centres wrapped into the box, as a sphere packing of diameter D0 (g(r) in D0).
spheres::SpherePacking centres_as_spheres(const PackingAnalysis& a) {
  spheres::SpherePacking s;
  s.box = a.box;
  s.positions.resize(static_cast<Eigen::Index>(a.shapes.size()), 3);
  for (std::size_t k = 0; k < a.shapes.size(); ++k)
    for (int d = 0; d < 3; ++d) {
      s.positions(static_cast<Eigen::Index>(k), d) = wrap_into_period(a.shapes[k].centre[d], a.box[d]);
    }
  s.radii = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(a.shapes.size()), 0.5 * a.d0);
  return s;
}

void check_distinct_centres(const packing::ShellPackingFile& p, const PackingAnalysis& a) {
  // The file's own unit, not --d0: a D0 of 1e308 made every pair of shells "duplicated".
  const double tol = 1e-9 * p.d0;
  for (std::size_t i = 0; i < a.shapes.size(); ++i)
    for (std::size_t j = i + 1; j < a.shapes.size(); ++j) {
      Eigen::Vector3d d = a.shapes[i].centre - a.shapes[j].centre;
      for (int k = 0; k < 3; ++k)
        if (p.periodic[k]) d[k] = minimum_image(d[k], p.box[k]);
      if (d.norm() <= tol)
        throw InputError(p.file, 0, fmt::format("shells {} and {} have the same centre (a duplicated shell)", i, j));
    }
}

}  // namespace

PackingAnalysis analyze_packing(const packing::ShellPackingFile& p, const AnalyzeOptions& o) {
  PackingAnalysis a;
  a.file = p.file;
  a.particles = p.shells();
  a.box = p.box;
  // D0 is the unit of g(r), about a shell's diameter: one larger than the box measures nothing.
  if (o.d0 && !(*o.d0 <= p.box.maxCoeff()))
    throw UsageError(fmt::format("--d0 {}: larger than the box of {} (largest side {}): D0 is about a shell's "
                                 "diameter", io::format_number(*o.d0), p.file, io::format_number(p.box.maxCoeff())));
  a.d0 = o.d0 ? *o.d0 : p.d0;
  a.d0_source = o.d0 ? "option" : p.d0_source;
  const auto& k = p.keys;
  a.bending = k.bending.value_or("");
  auto warn = [&](const std::string& what) { a.warnings.push_back(fmt::format("{}: {}", p.file, what)); };

  a.volumes = packing::shell_volumes(p.V, p.F, p.offsets);
  const double box_volume = p.box.prod();
  if (k.phi) {
    a.phi = *k.phi;
    a.phi_source = "file";
  } else {
    const auto& v = k.volume0.empty() ? a.volumes : k.volume0;
    double sum = 0;
    for (double x : v) sum += x;
    a.phi = sum / box_volume;
    a.phi_source = k.volume0.empty() ? "shell_volumes" : "volume0";
  }

  a.shapes = shell::shell_shapes(p.V, p.offsets);
  check_distinct_centres(p, a);
  a.turgor = k.turgor;
  a.p0 = o.p0 ? o.p0 : k.p0;
  if (a.turgor.empty()) warn("no turgor= line: the turgor columns are left empty");
  else if (!a.p0) warn("no P0= line (or --p0): turgor_mean_P0 is left empty");

  // Contacts follow the law the packing was made with (contact=, else hertz-vertices), with
  // its length: R_v (vertex_radius=, else the wall thickness, as shellpack shell's default)
  // or delta (contact_distance=, else the thickness); forces need E and nu too. The walls
  // always take R_v.
  shell::ContactParameters cp;
  a.contact = o.contact ? *o.contact : k.contact ? *k.contact : "hertz-vertices";
  const bool faces = a.contact == "hertz-faces";
  const auto rv = o.vertex_radius ? o.vertex_radius : k.vertex_radius ? k.vertex_radius : k.thickness;
  const auto delta = o.contact_distance ? o.contact_distance : k.contact_distance ? k.contact_distance : k.thickness;
  const auto reach = faces ? delta : rv;
  const auto E = o.youngs_modulus ? o.youngs_modulus : k.youngs_modulus;
  if (o.poisson_ratio || k.poisson_ratio) cp.poisson_ratio = o.poisson_ratio ? *o.poisson_ratio : *k.poisson_ratio;
  cp.wall_modulus = o.wall_modulus;
  cp.wall_poisson_ratio = o.wall_poisson_ratio;
  if (rv) cp.vertex_radius = *rv;
  if (delta) cp.contact_distance = *delta;
  cp.youngs_modulus = E ? *E : 1.0;  // contacts and Z do not depend on it
  if (reach) {
    neighbours::Box box;
    box.lengths = p.box;
    box.periodic = p.periodic;
    try {
      a.contacts = shell::shell_contacts(p.V, p.F, p.offsets, box, cp, a.contact);
    } catch (const UsageError& e) {  // the reach too large for the box: a problem of this file
      throw InputError(p.file, 0, fmt::format("{} = {}: {}", faces ? "delta" : "R_v", *reach, e.what()));
    }
    a.contacts_per_shell = shell::contacts_per_shell(a.contacts, a.particles);
    a.has_contacts = true;
    a.has_forces = E.has_value();
  }
  const std::string missing_key = faces ? "no contact_distance= or thickness= line" : "no vertex_radius= or thickness= line";
  const std::string flag = faces ? "--contact-distance" : "--vertex-radius";
  const bool walled = !all_periodic(p.periodic);
  if (!reach) {
    if (o.require_contacts) throw InputError(p.file, 0, missing_key + ": give " + flag + " for --contacts");
    warn(missing_key + " (or " + flag + "): contacts, Z, forces and walls are left empty");
  } else if (!E) {
    if (o.require_contacts) throw InputError(p.file, 0, "no E= line: give --youngs-modulus for the forces of --contacts");
    warn(std::string("no E= line (or --youngs-modulus): the force columns") + (walled ? " and the wall load" : "") +
         " are left empty");
  }
  if (walled && rv && E) a.walls = shell::wall_load(p.V, p.F, p.box, p.periodic, cp);

  if (all_periodic(p.periodic)) {
    const auto centres = centres_as_spheres(a);
    a.rdf = spheres::radial_distribution({centres}, o.bin_width, o.r_max);
    if (p.box[0] == p.box[1] && p.box[1] == p.box[2])
      a.voronoi_faces = shell::periodic_voronoi_face_counts(centres.positions, p.box[0]);
    else
      warn("the box is not a cube: CGAL's periodic triangulation needs one, the Voronoi columns are left empty");
  } else {
    if (o.require_rdf) throw InputError(p.file, 0, "not periodic on every axis: no g(r) for --rdf");
    warn("not periodic on every axis (walls): g(r) and the Voronoi columns are left out");
  }
  return a;
}

}  // namespace cmp::packrun
