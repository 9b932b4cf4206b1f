#pragma once
// Contact laws between lobes of different cells: the contact styles of the cell model. A law
// gives the pair energy V(delta) and the repulsive force magnitude dV/d delta for an overlap
// delta = (sigma_ik + sigma_jl)/2 - |r_ik - r_jl| > 0 (zero otherwise), in units of k sigma^2
// and k sigma. Each law is a struct in a header of its own (harmonic_law.hpp, hertz_law.hpp:
// name, description, energy, force) and one line of the table in contact_law.cpp, which also
// instantiates the force loop for it; --contact and --list-models come from the table, and the
// generic harness (tests/forcefield) checks every entry.
#include <string>
#include <vector>

namespace cmp::cells2d {

class ContactEngine;
struct Cell;

struct ContactLawStyle {
  const char* name;
  const char* description;
  double (*energy)(double overlap);
  double (*force)(double overlap);
  // The engine's force loop compiled for this law (ContactEngine::kernel<Law>).
  double (*kernel)(const ContactEngine& engine, const std::vector<Cell>& cells, double* force);
};

// Every registered contact law, the thesis's first.
const std::vector<ContactLawStyle>& contact_laws();
// The law of that name; throws cmp::UsageError "unknown contact law 'x' (known: ...)".
const ContactLawStyle& contact_law(const std::string& name);

}  // namespace cmp::cells2d
