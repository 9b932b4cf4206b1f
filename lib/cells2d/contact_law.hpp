#pragma once
// Contact laws between lobes of different cells: the contact styles of the cell model. A law
// gives the pair energy V(delta) and the repulsive force magnitude dV/d delta for an overlap
// delta = (sigma_ik + sigma_jl)/2 - |r_ik - r_jl| > 0 (zero otherwise), in units of k sigma^2
// and k sigma. Each law is a struct in a header of its own (harmonic_law.hpp, hertz_law.hpp:
// name, description, energy, force) and one line of the table in contact_law.cpp, which also
// instantiates the force loop for it; --contact and --list-models come from the table, and the
// generic harness (tests/forcefield) checks every entry. A law may reach beyond contact: it acts
// for overlap > -range(parameters) (the sticky law's attraction of width Delta), with an energy
// that vanishes at -range so that pairs entering and leaving the range change nothing.
#include <string>
#include <vector>

namespace cmp::cells2d {

class ContactEngine;
struct Cell;

// The parameters a law may read; every law takes them, most ignore them.
struct LawParameters {
  double attraction = 0;  // width Delta of the sticky law's attractive range [sigma] (S2.14)
};

struct ContactLawStyle {
  const char* name;
  const char* description;
  double (*energy)(double overlap, const LawParameters& parameters);
  // dV/d delta: positive pushes the lobes apart, negative pulls them together.
  double (*force)(double overlap, const LawParameters& parameters);
  // How far beyond contact the law acts [sigma]: 0 for the repulsive laws.
  double (*range)(const LawParameters& parameters);
  // The engine's force loop compiled for this law (ContactEngine::kernel<Law>).
  double (*kernel)(const ContactEngine& engine, const std::vector<Cell>& cells, double* force);
};

// Every registered contact law, the thesis's first.
const std::vector<ContactLawStyle>& contact_laws();
// The law of that name; throws cmp::UsageError "unknown contact law 'x' (known: ...)".
const ContactLawStyle& contact_law(const std::string& name);

}  // namespace cmp::cells2d
