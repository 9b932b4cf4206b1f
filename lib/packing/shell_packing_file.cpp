#include "packing/shell_packing_file.hpp"

#include "core/errors.hpp"
#include "io/input.hpp"
#include "io/parse_number.hpp"
#include "packing/packing_file.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <sstream>

namespace cmp::packing {

namespace {

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::vector<std::string> tokens(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

enum class Range { positive, poisson, any };

double number(const std::string& key, const std::string& value, Range range, const std::string& path, long line) {
  const auto t = tokens(value);
  if (t.size() != 1) throw InputError(path, line, fmt::format("{}= needs one number, got '{}'", key, value.substr(0, 60)));
  const double v = io::parse_double(t[0], path, line, key + "= as a number");
  if (range == Range::positive && !(v > 0)) throw InputError(path, line, fmt::format("{}= must be positive, got {}", key, t[0]));
  if (range == Range::poisson && !(v > -1 && v <= 0.5))
    throw InputError(path, line, fmt::format("{}= must lie in (-1, 0.5], got {}", key, t[0]));
  return v;
}

std::vector<double> numbers(const std::string& key, const std::string& value, bool positive, int count,
                            const std::string& path, long line) {
  const auto t = tokens(value);
  if (static_cast<int>(t.size()) != count)
    throw InputError(path, line, fmt::format("{}= needs one number per shell ({}), got {}", key, count, t.size()));
  std::vector<double> out;
  for (const auto& s : t) {
    const double v = io::parse_double(s, path, line, key + "= values as numbers");
    if (positive && !(v > 0)) throw InputError(path, line, fmt::format("{}= values must be positive, got {}", key, s));
    out.push_back(v);
  }
  return out;
}

}  // namespace

PackingKeys parse_packing_keys(const std::vector<std::string>& comments, const std::vector<long>& lines,
                               const std::string& path, int shells) {
  PackingKeys k;
  for (std::size_t c = 0; c < comments.size(); ++c) {
    const std::string& text = comments[c];
    const auto eq = text.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(text.substr(0, eq)), value = text.substr(eq + 1);
    const long line = c < lines.size() ? lines[c] : 0;
    if (key == "phi") k.phi = number(key, value, Range::positive, path, line);
    else if (key == "E") k.youngs_modulus = number(key, value, Range::positive, path, line);
    else if (key == "nu") k.poisson_ratio = number(key, value, Range::poisson, path, line);
    else if (key == "thickness") k.thickness = number(key, value, Range::positive, path, line);
    else if (key == "vertex_radius") k.vertex_radius = number(key, value, Range::positive, path, line);
    else if (key == "P0") k.p0 = number(key, value, Range::positive, path, line);
    else if (key == "turgor") k.turgor = numbers(key, value, false, shells, path, line);
    else if (key == "volume0") k.volume0 = numbers(key, value, true, shells, path, line);
    else if (key == "contact_distance") k.contact_distance = number(key, value, Range::positive, path, line);
    else if (key == "contact") {
      const auto t = tokens(value);
      if (t.size() != 1 || (t[0] != "hertz-vertices" && t[0] != "hertz-faces"))
        throw InputError(path, line, "contact= needs hertz-vertices or hertz-faces");
      k.contact = t[0];
    } else if (key == "bending") {
      const auto t = tokens(value);
      if (t.size() != 1) throw InputError(path, line, "bending= needs one style name (or none)");
      k.bending = t[0];
    }
  }
  return k;
}

ShellPackingFile read_shell_packing(const std::string& path) {
  io::Input input(path);
  if (input.format() != io::InputFormat::off) input.fail_format("a packing OFF of shells ('OFF' first, then '# box Lx Ly Lz')");
  auto packings = read_packings(input);
  auto& q = packings.back();
  ShellPackingFile p;
  p.file = path;
  p.box = q.box;
  p.periodic = q.periodic;
  p.offsets = std::move(q.shell_offsets);
  p.V = std::move(q.V);
  p.F = std::move(q.F);
  p.keys = parse_packing_keys(q.comments, q.comment_lines, path, p.shells());
  p.d0 = q.d0;
  p.d0_source = q.d0_source;
  if (p.d0_source != "file" && !p.keys.volume0.empty()) {
    double mean = 0;
    for (double v : p.keys.volume0) mean += v;
    p.d0 = std::cbrt(6 * mean / static_cast<double>(p.keys.volume0.size()) / M_PI);
    p.d0_source = "volume0";
  }
  return p;
}

}  // namespace cmp::packing
