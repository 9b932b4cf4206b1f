#include "shell/shell_model.hpp"

#include "shell/styles.hpp"

namespace cmp::shell {

ShellSystem make_shell_system(const mesh::TriMesh& rest, const ShellModel& m) {
  ShellSystem s(rest);
  s.add(stretching_style(m.stretching).make(rest, m.material));
  if (!m.bending.empty()) s.add(bending_style(m.bending).make(rest, m.material));
  if (!m.pressure.empty()) s.add(pressure_style(m.pressure).make(rest, m.load));
  if (m.walls) s.add(contact_style("hertz-walls").make(rest, m.contact));
  if (m.shell_contacts) s.add(contact_style("hertz-vertices").make(rest, m.contact));
  return s;
}

}  // namespace cmp::shell
