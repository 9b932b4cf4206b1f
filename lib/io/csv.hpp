#pragma once
// CSV tables with provenance (DESIGN.md):
//   # key=value        (parameters and provenance, above the header)
//   col_a,col_b_unit,...
//   1.5,2,...
// Numbers are written in the shortest form that reads back to the same double.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace cmp::io {

struct CsvTable {
  std::string file;                                          // for error messages
  std::vector<std::pair<std::string, std::string>> meta;     // "# key=value" lines, in order
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<long> row_lines;                               // line number of each row

  // Index of the named column; throws cmp::InputError naming the file and the header line.
  int column(const std::string& name) const;
  // The cell as a finite double; throws cmp::InputError with file:line when it is not one.
  double number(std::size_t row, int column) const;
};

// Strict reader: every row must have as many fields as the header. "-" reads stdin.
CsvTable read_csv(const std::string& path);

// Streams a table: meta lines, then the header, then rows (all rows same width as header).
class CsvWriter {
 public:
  explicit CsvWriter(std::ostream& out) : out_(out) {}
  void meta(const std::string& key, const std::string& value);
  void header(const std::vector<std::string>& columns);
  // A row of already formatted cells; see format_number() for doubles.
  void row(const std::vector<std::string>& cells);
 private:
  std::ostream& out_;
  std::size_t width_ = 0;
};

// Shortest representation that parses back to the same double ("0.1", "1e-08", "3").
std::string format_number(double x);

}  // namespace cmp::io
