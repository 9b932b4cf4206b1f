#include "shell/shell_model.hpp"

#include "shell/styles.hpp"

#include "io/csv.hpp"

namespace cmp::shell {

void write_model_meta(io::CsvWriter& csv, const ShellModel& m, const std::string& thickness_key) {
  csv.meta("stretching", m.stretching);
  csv.meta("bending", m.bending.empty() ? "none" : m.bending);
  csv.meta("pressure_model", m.pressure);
  csv.meta("E", io::format_number(m.material.youngs_modulus));
  csv.meta("nu", io::format_number(m.material.poisson_ratio));
  csv.meta(thickness_key, io::format_number(m.material.thickness));
  csv.meta("vertex_radius", io::format_number(m.contact.vertex_radius));
  if (m.shell_contacts) {
    csv.meta("contact", m.shell_contact_style);
    if (m.shell_contact_style == "hertz-faces") csv.meta("contact_distance", io::format_number(m.contact.contact_distance));
  }
}

ShellSystem make_shell_system(const mesh::TriMesh& rest, const ShellModel& m) {
  ShellSystem s(rest);
  s.add(stretching_style(m.stretching).make(rest, m.material));
  if (!m.bending.empty()) s.add(bending_style(m.bending).make(rest, m.material));
  if (!m.pressure.empty()) s.add(pressure_style(m.pressure).make(rest, m.load));
  if (m.walls) s.add(contact_style("hertz-walls").make(rest, m.contact));
  if (m.shell_contacts) s.add(contact_style(m.shell_contact_style).make(rest, m.contact));
  return s;
}

}  // namespace cmp::shell
