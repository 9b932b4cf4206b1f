#include "io/xyz_frame.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace cmp::io {

int XyzColumn::rows() const {
  if (width <= 0) return 0;
  const auto n = type == 'S' ? strings.size() : values.size();
  return static_cast<int>(n / static_cast<std::size_t>(width));
}

int XyzFrame::size() const {
  return columns.empty() ? 0 : columns.front().rows();
}

const XyzColumn* XyzFrame::find(const std::string& name) const {
  for (const auto& c : columns)
    if (c.name == name) return &c;
  return nullptr;
}

XyzColumn* XyzFrame::find(const std::string& name) {
  for (auto& c : columns)
    if (c.name == name) return &c;
  return nullptr;
}

void XyzFrame::fail(const std::string& what) const {
  if (file.empty()) throw std::invalid_argument("extended XYZ frame: " + what);
  throw InputError(file, line, what);
}

const XyzColumn& XyzFrame::column(const std::string& name, char type, int width) const {
  const auto* c = find(name);
  const auto wanted =
      width ? fmt::format("{}:{}:{}", name, type, width) : fmt::format("{}:{}", name, type);
  if (!c) fail("no column " + wanted + " in Properties");
  if (c->type != type || (width && c->width != width))
    fail(fmt::format("column {}:{}:{} found, expected {}", c->name, c->type, c->width, wanted));
  return *c;
}

mesh::VertexMatrix XyzFrame::positions() const {
  const auto& c = column("pos", 'R', 3);
  return Eigen::Map<const mesh::VertexMatrix>(c.values.data(), c.rows(), 3);
}

std::vector<std::string> XyzFrame::species() const {
  return column("species", 'S', 1).strings;
}

Eigen::MatrixXd XyzFrame::real_column(const std::string& name) const {
  const auto* c = find(name);
  if (!c) fail("no column '" + name + "' in Properties");
  if (c->type == 'S') fail("column '" + name + "' holds strings, expected numbers");
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  return Eigen::Map<const RowMajor>(c->values.data(), c->rows(), c->width);
}

const std::string* XyzFrame::find_info(const std::string& key) const {
  for (const auto& [k, v] : info)
    if (k == key) return &v;
  return nullptr;
}

void XyzFrame::add_column(XyzColumn c) {
  if (c.name.empty() || c.name.find_first_of(": \t\r\n\"'") != std::string::npos)
    throw std::invalid_argument("extended XYZ: bad column name '" + c.name + "'");
  if (c.type != 'R' && c.type != 'I' && c.type != 'S' && c.type != 'L')
    throw std::invalid_argument("extended XYZ: column '" + c.name + "' has type '" +
                                std::string(1, c.type) + "', expected R, I, S or L");
  if (c.width <= 0) throw std::invalid_argument("extended XYZ: column width must be positive");
  const auto n = c.type == 'S' ? c.strings.size() : c.values.size();
  if (n % static_cast<std::size_t>(c.width) != 0)
    throw std::invalid_argument(
        fmt::format("extended XYZ: column '{}' holds {} values, not a "
                    "multiple of its width {}",
                    c.name, n, c.width));
  auto* same = find(c.name);
  const bool only = columns.empty() || (columns.size() == 1 && same);
  if (!only && c.rows() != size())
    throw std::invalid_argument(
        fmt::format("extended XYZ: column '{}' has {} rows, the frame "
                    "has {} atoms",
                    c.name, c.rows(), size()));
  if (same)
    *same = std::move(c);
  else
    columns.push_back(std::move(c));
}

void XyzFrame::set_positions(const mesh::VertexMatrix& V) {
  XyzColumn c{"pos", 'R', 3, {}, {}};
  c.values.assign(V.data(), V.data() + V.size());  // row-major: atom after atom
  add_column(std::move(c));
}

void XyzFrame::set_species(const std::vector<std::string>& names) {
  add_column(XyzColumn{"species", 'S', 1, {}, names});
}

void XyzFrame::set_real_column(const std::string& name,
                               const Eigen::Ref<const Eigen::MatrixXd>& values) {
  XyzColumn c{name, 'R', static_cast<int>(values.cols()), {}, {}};
  c.values.reserve(static_cast<std::size_t>(values.size()));
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (Eigen::Index j = 0; j < values.cols(); ++j) c.values.push_back(values(i, j));
  add_column(std::move(c));
}

void XyzFrame::set_integer_column(const std::string& name, const std::vector<int>& values) {
  add_column(XyzColumn{name, 'I', 1, std::vector<double>(values.begin(), values.end()), {}});
}

void XyzFrame::set_info(const std::string& key, const std::string& value) {
  for (auto& [k, v] : info)
    if (k == key) {
      v = value;
      return;
    }
  info.emplace_back(key, value);
}

}  // namespace cmp::io
