#include "cells2d/packing_xyz.hpp"
#include "core/minimum_image.hpp"

#include "core/errors.hpp"
#include "io/xyz.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace cmp::cells2d {

namespace {

Cell wrapped(const Cell& c, double L) {
  Cell w = c;
  w.x = wrap_into_period(c.x, L), w.y = wrap_into_period(c.y, L);
  return w;
}

// The cell of two lobe centres in a periodic box: the bud is taken at its nearest image.
Cell cell_from_lobe_rows(const Eigen::Vector2d& mother, Eigen::Vector2d bud_centre, double bud, double L) {
  for (int a = 0; a < 2; ++a) {
    const double n = std::nearbyint((mother[a] - bud_centre[a]) / L);
    if (n != 0) bud_centre[a] += n * L;
  }
  return cell_from_lobes(mother, bud_centre, bud);
}

}  // namespace

std::vector<Cell> canonical_cells(const std::vector<Cell>& cells, double box) {
  std::vector<Cell> out;
  out.reserve(cells.size());
  for (const Cell& c : cells) {
    const Cell w = wrapped(c, box);
    const double bud = 2 * (0.5 * w.bud);
    Cell r = cell_from_lobe_rows(lobe_centre(w, 0), lobe_centre(w, 1), bud, box);
    r.rate0 = c.rate0, r.rate = c.rate;
    out.push_back(r);
  }
  return out;
}

void set_lobe_columns(io::XyzFrame& frame, const std::vector<Cell>& cells) {
  const auto lobes = static_cast<Eigen::Index>(2 * cells.size());
  mesh::VertexMatrix pos(lobes, 3);
  Eigen::VectorXd radius(lobes), orientation(lobes);
  std::vector<int> cell_id(static_cast<std::size_t>(lobes)), lobe(static_cast<std::size_t>(lobes));
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const std::size_t l = 2 * i + static_cast<std::size_t>(k);
      const auto r = static_cast<Eigen::Index>(l);
      const Eigen::Vector2d p = lobe_centre(cells[i], k);
      pos.row(r) << p[0], p[1], 0.0;
      radius[r] = 0.5 * lobe_diameter(cells[i], k);
      orientation[r] = cells[i].theta;
      cell_id[l] = static_cast<int>(i), lobe[l] = k;
    }
  frame.set_species(std::vector<std::string>(static_cast<std::size_t>(lobes), "X"));
  frame.set_positions(pos);
  frame.set_real_column("radius", radius);
  frame.set_integer_column("cell", cell_id);
  frame.set_integer_column("lobe", lobe);
  frame.set_real_column("orientation", orientation);
}

io::XyzFrame packing_frame(const std::vector<Cell>& cells, double box, const PackingAnalysis* analysis,
                           const std::vector<std::pair<std::string, std::string>>& info) {
  io::XyzFrame frame;
  frame.has_lattice = true;
  frame.lattice = Eigen::Matrix3d::Identity();
  frame.lattice(0, 0) = frame.lattice(1, 1) = box;
  frame.pbc = {true, true, false};
  std::vector<Cell> wrapped_cells;
  wrapped_cells.reserve(cells.size());
  for (const Cell& c : cells) wrapped_cells.push_back(wrapped(c, box));
  set_lobe_columns(frame, wrapped_cells);
  const std::size_t lobes = 2 * cells.size();
  Eigen::VectorXd pressure(static_cast<Eigen::Index>(lobes));
  std::vector<int> contacts(lobes, 0);
  for (std::size_t l = 0; l < lobes; ++l) {
    pressure[static_cast<Eigen::Index>(l)] = analysis ? analysis->lobe_pressure(cells, static_cast<int>(l)) : 0.0;
    if (analysis) contacts[l] = analysis->lobe_contacts[l];
  }
  frame.set_real_column("pressure", pressure);
  frame.set_integer_column("contacts", contacts);
  for (const auto& [k, v] : info) frame.set_info(k, v);
  return frame;
}

CellPacking packing_from_frame(const io::XyzFrame& frame) {
  CellPacking p;
  p.file = frame.file, p.line = frame.line, p.info = frame.info;
  const long comment = frame.line + 1;
  const auto fail = [&](long line, const std::string& what) -> void {
    if (frame.file.empty()) throw std::invalid_argument(what);
    throw InputError(frame.file, line, what);
  };
  if (!frame.has_lattice) fail(comment, "no Lattice: a cell packing needs its box");
  const Eigen::Matrix3d& L = frame.lattice;
  if (!(L(0, 0) > 0) || !(L(1, 1) > 0) || !std::isfinite(L(0, 0)))
    fail(comment, fmt::format("the box must have positive sides, got {} by {}", L(0, 0), L(1, 1)));
  if (L(0, 1) != 0 || L(0, 2) != 0 || L(1, 0) != 0 || L(1, 2) != 0 || L(2, 0) != 0 || L(2, 1) != 0)
    fail(comment, "the Lattice must be diagonal");
  if (L(0, 0) != L(1, 1)) fail(comment, fmt::format("the box must be square, got {} by {}", L(0, 0), L(1, 1)));
  if (!frame.pbc[0] || !frame.pbc[1]) fail(comment, "the packing must be periodic in x and y (pbc=\"T T F\")");
  p.box = L(0, 0);
  const mesh::VertexMatrix pos = frame.positions();
  const Eigen::MatrixXd radius = frame.real_column("radius");
  const Eigen::MatrixXd cell = frame.real_column("cell");
  const Eigen::MatrixXd lobe = frame.real_column("lobe");
  (void)frame.column("cell", 'I', 1), (void)frame.column("lobe", 'I', 1);
  const int rows = frame.size();
  if (rows == 0) fail(frame.line, "no cells in the frame");
  struct Rows { int mother = -1, bud = -1; };
  std::map<long, Rows> by_id;
  const auto row_line = [&](int r) { return frame.line + 2 + r; };
  for (int r = 0; r < rows; ++r) {
    const long id = static_cast<long>(cell(r, 0));
    const double l = lobe(r, 0), rad = radius(r, 0);
    if (l != 0 && l != 1) fail(row_line(r), fmt::format("lobe must be 0 (mother) or 1 (bud), got {}", l));
    if (!std::isfinite(pos(r, 0)) || !std::isfinite(pos(r, 1))) fail(row_line(r), "non-finite position");
    Rows& slot = by_id[id];
    int& mine = l == 0 ? slot.mother : slot.bud;
    if (mine >= 0)
      fail(row_line(r), fmt::format("cell {} appears again as a {} (first at line {}): each cell has exactly one "
                                    "mother and one bud row",
                                    id, l == 0 ? "mother" : "bud", row_line(mine)));
    mine = r;
    if (l == 0 && std::abs(rad - 0.5) > 1e-12)
      fail(row_line(r), fmt::format("mother radius must be 1/2 (the unit sigma is the mother diameter), got {}", rad));
    if (l == 1 && !(rad >= 0 && rad <= 0.5))
      fail(row_line(r), fmt::format("bud radius must lie in [0, 1/2] (not larger than its mother), got {}", rad));
  }
  for (const auto& [id, s] : by_id) {
    if (s.mother < 0) fail(row_line(s.bud), fmt::format("cell {} has a bud row but no mother row", id));
    if (s.bud < 0) fail(row_line(s.mother), fmt::format("cell {} has a mother row but no bud row", id));
    const double bud = 2 * radius(s.bud, 0);
    const Eigen::Vector2d m(pos(s.mother, 0), pos(s.mother, 1));
    const Cell c = cell_from_lobe_rows(m, Eigen::Vector2d(pos(s.bud, 0), pos(s.bud, 1)), bud, p.box);
    Eigen::Vector2d d = m - Eigen::Vector2d(pos(s.bud, 0), pos(s.bud, 1));
    for (int a = 0; a < 2; ++a) d[a] = minimum_image(d[a], p.box);
    if (std::abs(d.norm() - 0.5 * (1 + bud)) > 1e-6)
      fail(row_line(s.bud), fmt::format("the bud of cell {} is {} from its mother's centre; tangent lobes are {} apart",
                                        id, d.norm(), 0.5 * (1 + bud)));
    p.cells.push_back(c);
  }
  return p;
}

std::vector<CellPacking> read_packings(const std::string& path) {
  std::vector<CellPacking> out;
  for (const io::XyzFrame& f : io::read_xyz(path)) out.push_back(packing_from_frame(f));
  return out;
}

}  // namespace cmp::cells2d
