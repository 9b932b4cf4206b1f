#include "shell/styles.hpp"

#include "shell/dead_load.hpp"
#include "shell/dihedral_hinges.hpp"
#include "shell/edge_springs.hpp"
#include "shell/hertz_contacts.hpp"
#include "shell/svk_membrane.hpp"
#include "shell/turgor_pressure.hpp"
#include "shell/vertex_face_contacts.hpp"

#include "core/registry.hpp"

namespace cmp::shell {

namespace {

// A spring style: the rule and the name it is registered under.
template <SpringConstants rule>
std::unique_ptr<EnergyTerm> make_springs(const mesh::TriMesh& rest, const MaterialParameters& p) {
  const char* name = rule == SpringConstants::SeungNelson ? "springs-seung-nelson"
                     : rule == SpringConstants::Kot       ? "springs-kot"
                                                          : "springs-van-gelder";
  return std::make_unique<EdgeSprings>(rest, p, rule, name);
}

const StretchingStyle kStretching[] = {
    {"springs-seung-nelson", "harmonic edge springs, k = sqrt(3) E t / 2 (Seung-Nelson, B.22; nu = 1/3)",
     &make_springs<SpringConstants::SeungNelson>},
    {"springs-kot", "harmonic edge springs, k = 2 E t A_0 / ((1 - nu) sum L^2) (Kot et al., B.26)",
     &make_springs<SpringConstants::Kot>},
    {"springs-van-gelder", "harmonic edge springs, per-edge k from the rest triangles (Van Gelder, B.27)",
     &make_springs<SpringConstants::VanGelder>},
    {"svk", "St Venant-Kirchhoff membrane, biquadratic triangle springs (the FEM of B.28-B.34)",
     [](const mesh::TriMesh& r, const MaterialParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<SvkMembrane>(r, p);
     }},
};

const BendingStyle kBending[] = {
    {"hinge", "dihedral hinges with a curved rest state, kappa = E t^3 / (12 (1 - nu^2)) (B.37-B.44)",
     [](const mesh::TriMesh& r, const MaterialParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<DihedralHinges>(r, p);
     }},
    {"hinge-uniform", "normal-vector springs, one stiffness 2 kappa / sqrt(3) on every hinge, curved rest (B.35-B.36)",
     [](const mesh::TriMesh& r, const MaterialParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<DihedralHinges>(r, p, HingeStiffness::Uniform, "hinge-uniform");
     }},
};

const PressureStyle kPressure[] = {
    {"turgor", "constant turgor pressure Pi, energy -Pi V of the signed enclosed volume (B.2.4)",
     [](const mesh::TriMesh& r, const PressureParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<TurgorPressure>(r, p);
     }},
    {"volume", "constant volume: Pi updated between relaxations, Pi <- Pi (1 + (V0 - V)/V), until |V - V0| <= 0.1 % V0 (5.2.1)",
     [](const mesh::TriMesh& r, const PressureParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<TurgorPressure>(r, p, PressureControl::ConstantVolume);
     }},
};

const ContactStyle kContact[] = {
    {"hertz-vertices", "Hertz repulsion of vertex spheres (radius R_v) of different shells, over linked cells (B.60)",
     [](const mesh::TriMesh& r, const ContactParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<VertexContacts>(r, p);
     }},
    {"hertz-faces", "Hertz repulsion of every vertex from the closest triangle of each other shell within delta (B.60 with R* = delta/2)",
     [](const mesh::TriMesh& r, const ContactParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<VertexFaceContacts>(r, p);
     }},
    {"hertz-walls", "Hertz repulsion of vertex spheres (radius R_v) from rigid planes (B.60 with R* = R_v)",
     [](const mesh::TriMesh& r, const ContactParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<WallContacts>(r, p);
     }},
};

const LoadStyle kLoad[] = {
    {"load", "dead load: fixed forces f_i on the vertices, E = -sum_i f_i . x_i (the plate benchmarks' loads, B.5.3-B.5.4)",
     [](const mesh::TriMesh& r, const LoadParameters& p) -> std::unique_ptr<EnergyTerm> {
       return std::make_unique<DeadLoad>(r.V.rows(), p.forces.empty() ? std::vector<double>(3 * r.V.rows(), 0.0) : p.forces);
     }},
};

}  // namespace

std::span<const StretchingStyle> stretching_styles() { return kStretching; }
std::span<const BendingStyle> bending_styles() { return kBending; }
std::span<const PressureStyle> pressure_styles() { return kPressure; }
std::span<const ContactStyle> contact_styles() { return kContact; }
std::span<const LoadStyle> load_styles() { return kLoad; }

const StretchingStyle& stretching_style(const std::string& name) { return find_style(stretching_styles(), name, "stretching model"); }
const BendingStyle& bending_style(const std::string& name) { return find_style(bending_styles(), name, "bending model"); }
const PressureStyle& pressure_style(const std::string& name) { return find_style(pressure_styles(), name, "pressure model"); }
const ContactStyle& contact_style(const std::string& name) { return find_style(contact_styles(), name, "contact model"); }
const LoadStyle& load_style(const std::string& name) { return find_style(load_styles(), name, "load model"); }

void write_model_list(std::ostream& out) {
  write_style_header(out);
  write_styles(out, "stretching", stretching_styles());
  write_styles(out, "bending", bending_styles());
  write_styles(out, "pressure", pressure_styles());
  write_styles(out, "contact", contact_styles());
  write_styles(out, "load", load_styles());
}

}  // namespace cmp::shell
