#pragma once
// A shell model as a user chooses it: the style of each kind by its registered name and the
// parameters, and the system it builds on a rest mesh.
#include "shell/shell_parameters.hpp"
#include "shell/shell_system.hpp"

#include <string>

namespace cmp::io {
class CsvWriter;
}

namespace cmp::shell {

struct ShellModel {
  std::string stretching = "svk";  // a name of stretching_styles()
  std::string bending;             // a name of bending_styles(), or "" for a membrane
  std::string pressure;            // a name of pressure_styles(), or "" for none
  MaterialParameters material;
  PressureParameters load;         // the starting turgor
  bool walls = false;              // add hertz-walls (the planes in contact.walls, may be set later)
  bool shell_contacts = false;     // add the contact style between the shells of the mesh
  std::string shell_contact_style = "hertz-vertices";  // its name: hertz-vertices or hertz-faces
  ContactParameters contact;
};

// The model as `# key=value` lines of a CSV: stretching, bending (or none), pressure_model, E, nu,
// the thickness under `thickness_key` ("t" in shellpack shell's table), vertex_radius, and with
// shell contacts the contact style (and contact_distance for hertz-faces).
void write_model_meta(io::CsvWriter& csv, const ShellModel& model, const std::string& thickness_key);

// The system of `rest` with the model's terms, in the order stretching, bending, pressure,
// walls, shell contacts. Throws cmp::UsageError for an unknown style name or bad parameters.
ShellSystem make_shell_system(const mesh::TriMesh& rest, const ShellModel& model);

}  // namespace cmp::shell
