#pragma once
// The contacts between the shells of a packing and the forces they carry (thesis Ch. 4,
// Eqs. S4.1-S4.5), from the contact style the packing was made with (shell_contact_term.hpp):
// hertz-vertices (Eq. B.60: two shells touch when a vertex of one overlaps a vertex of the
// other, distance < 2 R_v) or hertz-faces (a vertex of one within delta of the other's
// surface), minimum image along the periodic axes. One contact is one pair of shells in one
// relative periodic image: in a small box a shell can touch a neighbour and that neighbour's
// image on its other side, two contacts.
//
// For the contact (m, n), f_i is the Hertz force that n exerts on vertex i of m (as the pushed
// vertex, or as a corner of a pushed triangle, by its barycentric weight), and
//   F_mn      = sum_i f_i                                             (S4.1-S4.4)
//   F_mn^perp = (1/3) sum_i sum_{j(i)} (A_j / C_i) |f_i . n_j| f_i/|f_i|   (S4.5)
// over the faces j(i) around i (area A_j, outward unit normal n_j) with C_i the barycentric
// dual area (Eq. A.1): the part of F_mn normal to the contact surface. The rest,
// F_mn - F_mn^perp, is tangential. The thesis's text calls the two the other way round
// (docs/thesis-departures.md); mu_eff = max |tangential| / |normal| (Fig. S4.1).
#include "neighbours/box.hpp"
#include "shell/shell_parameters.hpp"

#include "mesh/tri_mesh.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cmp::shell {

struct ShellContact {
  int m = 0, n = 0;            // the force is the one on shell m from shell n
  Eigen::Vector3i image = Eigen::Vector3i::Zero();  // n's periodic image seen from m [box sides]
  int vertex_pairs = 0;        // contacts of single vertices (pairs of vertices, vertex and triangle)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();       // F_mn [force]
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();      // Eq. S4.5 from m's side
  Eigen::Vector3d tangential = Eigen::Vector3d::Zero();  // F_mn - normal
};

// Every contact of the packing, in both directions: (m, n, k) and (n, m, -k) are two entries
// (their forces are opposite, Newton's third law; their normal parts are each computed on
// its own shell's surface). Sorted by m, n, image. V: the vertices, each shell unwrapped into
// one periodic image (offsets as in shell_shapes.hpp); F: outward-oriented faces, each within
// one shell; box: the periodic axes and their lengths (box.lengths; the non-periodic axes are
// ignored); p: R_v or delta, E, nu (walls unused); style: hertz-vertices or hertz-faces.
// Throws cmp::UsageError for an unknown style or a contact reach too large for a periodic side.
std::vector<ShellContact> shell_contacts(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
                                         const std::vector<int>& offsets, const neighbours::Box& box,
                                         const ContactParameters& p, const std::string& style = "hertz-vertices");

// Contacts of each shell (entries with m = k): #shells counts; their mean is Z.
std::vector<int> contacts_per_shell(const std::vector<ShellContact>& contacts, int shells);

// mu_eff = max over the contacts of |tangential| / |normal| (contacts with a zero normal part
// skipped); 0 when there is none.
double effective_friction(const std::vector<ShellContact>& contacts);

}  // namespace cmp::shell
