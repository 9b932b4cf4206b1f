#pragma once
// CSV tables with provenance (docs/formats.md):
//   # key=value        (parameters and provenance, above the header)
//   col_a,col_b_unit,...
//   1.5,2,...
// Numbers are written in the shortest form that reads back to the same double. Fields follow
// RFC 4180: a field holding a comma, a double quote or a line break is quoted ("a,b"), with
// inner quotes doubled. Blank lines are skipped; a '#' line after the header is a comment.
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
  long header_line = 0;                                      // line number of the header

  // Value of the first "# key=value" line with this key, or nullptr.
  const std::string* find_meta(const std::string& key) const;

  // Index of the named column; throws cmp::InputError naming the file, the header line and
  // the columns there are.
  int column(const std::string& name) const;
  // The cell as a finite double (spaces around it allowed); throws cmp::InputError with
  // file:line when it is not one, std::out_of_range for a row or column past the table.
  double number(std::size_t row, int column) const;
  // The cell as a whole decimal integer within [lo, hi] (spaces around it allowed): "1e300",
  // "2.5" or "99999999999" in an int column are cmp::InputError with file:line; throws
  // std::out_of_range as number().
  long long integer(std::size_t row, int column, long long lo, long long hi) const;
};

class Input;

// Strict reader: every row must have as many fields as the header, header names are unique,
// quotes are balanced. Throws cmp::InputError(file, line, what) otherwise, "empty file" for a
// file without a header. "-" reads stdin.
CsvTable read_csv(const std::string& path);
// Same, from an opened input.
CsvTable read_csv(Input& input);

// Streams a table: meta lines, then the header, then rows (all rows same width as header).
//
// Every number written is finite (docs/conventions.md): a cell that reads as a non-finite
// number ("nan", "inf", "-inf", as format_number writes them) is refused with
// cmp::ComputationError naming its column, so the run fails (exit 1) instead of writing a table
// its readers refuse. A table whose format documents infinite values (kcfit's undefined
// standard errors, jam2d's P0 = inf for no feedback) says so with allow_infinity(); NaN is
// refused always.
class CsvWriter {
 public:
  explicit CsvWriter(std::ostream& out) : out_(out) {}
  void allow_infinity() { infinity_allowed_ = true; }
  // "# key=value"; only before header(). Line breaks in value become spaces. Throws
  // std::logic_error after the header, std::invalid_argument for an empty key or one holding
  // '=', '#' or a line break.
  void meta(const std::string& key, const std::string& value);
  // The header row; sets the width of every row. Throws std::logic_error when called twice.
  void header(const std::vector<std::string>& columns);
  // The same for a table whose meta lines and header an earlier run wrote (a run resumed from
  // its checkpoint appends rows): sets the width, writes nothing.
  void header_written_before(const std::vector<std::string>& columns);
  // A row of already formatted cells; see format_number() for doubles. Throws
  // std::invalid_argument when the width differs from the header's, std::logic_error before
  // the header.
  void row(const std::vector<std::string>& cells);
 private:
  std::ostream& out_;
  std::size_t width_ = 0;
  bool has_header_ = false;
  bool infinity_allowed_ = false;
  std::vector<std::string> columns_;
  long rows_ = 0;
};

// Shortest representation that parses back to the same double ("0.1", "1e-08", "3", "-0");
// "nan", "inf" and "-inf" for the non-finite values (which number() rejects on reading).
std::string format_number(double x);

// One CSV field as written: quoted (RFC 4180) when it holds a comma, a quote, a line break,
// or starts with '#' or a space (so it cannot read as a comment or lose its spaces), else
// unchanged.
std::string csv_field(const std::string& cell);

}  // namespace cmp::io
