// Shell mechanics speed (make bench): force evaluations and FIRE iterations per second for one
// shell of 642, 2562 and 10242 vertices (SVK + hinge-uniform + turgor), on the threads given
// by OMP_NUM_THREADS, and the time to inflate a 2562-vertex shell to equilibrium.
// Prints "name,value,unit" rows.
//   bench_shell                 the rows above
//   bench_shell terms LEVEL     microseconds per add_gradient of each term, and per forces()
//   bench_shell inflate LEVEL   one inflation to equilibrium (for perf and the threads-under-load table)
//   bench_shell contacts LEVEL  ns per vertex of add_gradient of hertz-vertices and hertz-faces on
//                               50 shells (D0 = 1) in a periodic box: spheres just touching, and
//                               cubes with every facet in contact (the confluent limit); and the
//                               check that no vertex lies inside another shell on both, beside
//                               the winding numbers it replaced (5 of the 50 shells, times 10)
#include "shell/hertz_contacts.hpp"
#include "shell/penetration.hpp"
#include "shell/relax.hpp"
#include "shell/shell_packing.hpp"
#include "shell/vertex_face_contacts.hpp"
#include "shell/shell_model.hpp"

#include "spheremesh/subdivision.hpp"

#include "core/minimum_image.hpp"
#include "mesh/point_in_mesh.hpp"

#include <chrono>
#include <cstdio>
#include <string>

using namespace cmp;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

shell::ShellModel model() {
  shell::ShellModel m;
  m.bending = "hinge-uniform";
  m.pressure = "turgor";
  m.material = {25.0, 1.0 / 3.0, 0.1};
  m.load.turgor = 0.25;
  return m;
}

mesh::TriMesh sphere(int level) { return spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, 2.5); }

shell::RelaxParameters relax_parameters(const mesh::TriMesh& rest, const shell::ShellModel& m) {
  shell::RelaxParameters rp;
  rp.force_scale = shell::default_force_scale(rest, m.material.youngs_modulus, m.material.thickness);
  rp.relative_tolerance = 1e-9;
  return rp;
}

// Seconds per call of f, over enough calls for about 0.3 s.
template <class F>
double per_call(F&& f) {
  f();  // warm: the contact styles build their Verlet lists at the first call
  long reps = 1;
  for (;;) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < reps; ++k) f();
    const double sec = seconds_since(t0);
    if (sec > 0.3) return sec / reps;
    reps *= 2;
  }
}

void terms(int level) {
  const auto m = model();
  const auto rest = sphere(level);
  auto s = shell::make_shell_system(rest, m);
  const Eigen::VectorXd x = 1.01 * s.x;
  Eigen::VectorXd g(x.size()), f;
  const long v = rest.V.rows();
  for (const auto& t : s.terms()) {
    const double sec = per_call([&] { t->add_gradient(shell::span_of(x), shell::span_of(g)); });
    std::printf("gradient_%s_%ld,%.2f,us\n", t->name().c_str(), v, 1e6 * sec);
  }
  std::printf("forces_%ld,%.2f,us\n", v, 1e6 * per_call([&] { s.forces(x, f); }));
}

void inflate(int level) {
  const auto m = model();
  const auto rest = sphere(level);
  auto s = shell::make_shell_system(rest, m);
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = shell::relax(s, relax_parameters(rest, m));
  std::printf("inflate_%ld,%.3f,s (%ld FIRE iterations)\n", static_cast<long>(rest.V.rows()), seconds_since(t0),
              r.iterations);
}

// 50 shells of `level` (D0 = 1) on a 5 x 5 x 2 lattice in a periodic box: spheres whose
// surfaces overlap by 0.02 D0 along the lattice axes, or the same meshes blown up onto cubes of
// side 1 whose facets lie 0.01 apart (every facet vertex in contact, as at confluence). R_v =
// 0.75 of the largest circumradius (the packing default), delta = t = 0.02.
void contacts(int level) {
  const auto one = spheremesh::subdivided_sphere(spheremesh::Subdivision::Icosahedron, level, 0.5);
  const long nv = one.V.rows(), nf = one.F.rows();
  for (const bool cube : {false, true}) {
    mesh::TriMesh cell = one;
    if (cube)
      for (long v = 0; v < nv; ++v) cell.V.row(v) *= 0.5 / cell.V.row(v).cwiseAbs().maxCoeff();
    const double spacing = cube ? 1.01 : 0.98;
    mesh::TriMesh m;
    m.V.resize(50 * nv, 3);
    m.F.resize(50 * nf, 3);
    for (int k = 0; k < 50; ++k) {
      const Eigen::RowVector3d c(spacing * (k % 5), spacing * (k / 5 % 5), spacing * (k / 25));
      m.V.middleRows(k * nv, nv) = cell.V.rowwise() + c;
      m.F.middleRows(k * nf, nf) = one.F.array() + static_cast<int>(k * nv);
    }
    shell::ContactParameters p;
    p.vertex_radius = 0.75 * shell::max_circumradius(cell);
    p.contact_distance = 0.02;
    p.box = Eigen::Vector3d(5 * spacing, 5 * spacing, 2 * spacing);
    const shell::VertexContacts spheres(m, p);
    const shell::VertexFaceContacts faces(m, p);
    const std::vector<double> x(m.V.data(), m.V.data() + m.V.size());
    std::vector<double> g(x.size(), 0.0);
    const long n = m.V.rows();
    const std::string shape = cube ? "cubes" : "spheres";
    const double ts = per_call([&] { spheres.add_gradient(x, g); });
    const double tf = per_call([&] { faces.add_gradient(x, g); });
    std::printf("gradient_hertz_vertices_%s_%ld,%.1f,ns/vertex (%zu contacts)\n", shape.c_str(), n, 1e9 * ts / n,
                spheres.touches(x).size());
    std::printf("gradient_hertz_faces_%s_%ld,%.1f,ns/vertex (%zu contacts)\n", shape.c_str(), n, 1e9 * tf / n,
                faces.touches(x).size());
    // The penetration check as compress runs it after every step, and the winding number of
    // every vertex in a shell's bounding sphere (the check before the ray-crossing query).
    const Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    const auto shells = shell::shell_partition(m.F, static_cast<int>(n));
    std::size_t found = 0;
    const double tp = per_call([&] { found = shell::penetrations(xv, m.F, shells, p.box).size(); });
    const auto t0 = std::chrono::steady_clock::now();
    long tested = 0, inside = 0;
    for (int k = 0; k < 5; ++k) {
      const mesh::FaceMatrix Fs = m.F.middleRows(k * nf, nf);
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      double reach = 0;
      for (long v = k * nv; v < (k + 1) * nv; ++v) centre += xv.segment<3>(3 * v) / static_cast<double>(nv);
      for (long v = k * nv; v < (k + 1) * nv; ++v) reach = std::max(reach, (xv.segment<3>(3 * v) - centre).norm());
      for (long v = 0; v < n; ++v) {
        if (v / nv == k) continue;
        Eigen::Vector3d d = xv.segment<3>(3 * v) - centre;
        for (int a = 0; a < 3; ++a) d[a] = minimum_image(d[a], (*p.box)[a]);
        if (d.norm() > reach) continue;
        ++tested;
        inside += mesh::winding_number(xv.data(), Fs, 0, nf, centre + d) > 0.5;
      }
    }
    std::printf("penetration_check_%s_%ld,%.1f,ms (%zu inside; winding numbers: %.0f ms, %ld tests in 5 of 50 shells "
                "(%ld inside), times 10)\n",
                shape.c_str(), n, 1e3 * tp, found, 1e4 * seconds_since(t0), tested, inside);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "terms") return terms(std::stoi(argv[2])), 0;
  if (argc == 3 && std::string(argv[1]) == "inflate") return inflate(std::stoi(argv[2])), 0;
  if (argc == 3 && std::string(argv[1]) == "contacts") return contacts(std::stoi(argv[2])), 0;
  if (argc != 1) {
    std::fprintf(stderr, "usage: bench_shell [terms LEVEL | inflate LEVEL | contacts LEVEL]\n");
    return 2;
  }
  const auto m = model();
  for (int level : {4, 5, 6}) {
    const auto rest = sphere(level);
    auto s = shell::make_shell_system(rest, m);
    Eigen::VectorXd x = 1.01 * s.x, f;
    const double per = per_call([&] { s.forces(x, f); });
    std::printf("force_evaluations_%ld,%.1f,1/s\n", static_cast<long>(rest.V.rows()), 1.0 / per);
    std::printf("triangle_forces_%ld,%.3g,1/s\n", static_cast<long>(rest.V.rows()), rest.F.rows() / per);
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = shell::relax(s, relax_parameters(rest, m));
    const double sec = seconds_since(t0);
    std::printf("fire_iterations_per_s_%ld,%.1f,1/s\n", static_cast<long>(rest.V.rows()), r.iterations / sec);
    if (level == 5) std::printf("inflate_2562_to_equilibrium,%.3f,s (%ld FIRE iterations)\n", sec, r.iterations);
  }
  // Forces of 40962 vertices, the size of a packing of 16 shells of 2562, where the force
  // passes run on all threads (element_assembly.hpp).
  {
    const auto rest = sphere(7);
    auto s = shell::make_shell_system(rest, m);
    Eigen::VectorXd x = 1.01 * s.x, f;
    const double per = per_call([&] { s.forces(x, f); });
    std::printf("force_evaluations_%ld,%.1f,1/s\n", static_cast<long>(rest.V.rows()), 1.0 / per);
    std::printf("triangle_forces_%ld,%.3g,1/s\n", static_cast<long>(rest.V.rows()), rest.F.rows() / per);
  }
}
