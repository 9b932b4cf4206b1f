#pragma once
// The rows a fit reads: several CSV tables with the same columns taken as one (each row keeps
// its file and line for messages), kept by conditions on columns (kcfit --where delta=0.04)
// and split into groups by the values of columns (kcfit --group-by delta,particles).
#include "io/csv.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace cmp::fit {

struct Rows {
  std::vector<std::string> header;                       // the columns every table has
  std::vector<std::pair<std::string, std::string>> meta;  // "# key=value" lines of the first table
  std::vector<std::vector<std::string>> cells;           // one entry per row, header.size() cells
  std::vector<std::size_t> source;                       // per row: index into files
  std::vector<long> lines;                               // per row: its line in that file
  std::vector<std::string> files;                        // the tables' names, in order
  long header_line = 0;                                  // of the first table

  // Index of the named column, or -1.
  int find(const std::string& name) const;
  // Index of the named column; throws cmp::InputError(first file, header line, "no column
  // 'name'; columns: ...") otherwise. what (e.g. "--x") is named in the message when given.
  int column(const std::string& name, const std::string& what = "") const;
  // The cell as a finite double; throws cmp::InputError(file, line, "column 'c': expected a
  // number, got '...'") otherwise.
  double number(std::size_t row, int column) const;
};

// The tables' rows, in order. Throws cmp::InputError(file, header line, ...) naming the first
// file when a table's columns differ from the first table's (same names in the same order),
// and std::invalid_argument for no table.
Rows merge_tables(const std::vector<io::CsvTable>& tables);

enum class Compare { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual };

// One condition "column OP value" with OP one of = == != < <= > >=, e.g. "delta=0.04".
struct Condition {
  std::string column;
  Compare op = Compare::Equal;
  double value = 0;
  std::string text;  // as typed, for messages
};

// Parses a condition; throws cmp::UsageError("--where: ...") for a missing column name or
// operator, or a value that is not a number.
Condition parse_condition(const std::string& text);

// Whether x satisfies the condition. Equality is numeric with a relative tolerance of 1e-9
// (so "0.04" matches 0.040 and 0.04000000000000001, as formatting differs between writers);
// < and > are strict beyond that tolerance, <= and >= include it.
bool satisfies(const Condition& condition, double x);

// Indices of the rows meeting every condition, in order. Throws cmp::InputError for a
// condition naming no column (first file, header line) or a cell that is not a number.
std::vector<std::size_t> select_rows(const Rows& rows, const std::vector<Condition>& conditions);

// Rows with the same values of the group columns.
struct Group {
  std::vector<double> key;         // one value per group column
  std::vector<std::size_t> rows;   // indices into Rows, in order
};

// Splits the selected rows by the values of the columns (numbers equal to 12 significant
// digits count as one value), groups in increasing order of their key (first column first).
// No columns: one group of all selected rows. Throws cmp::InputError for a cell that is not
// a number.
std::vector<Group> group_rows(const Rows& rows, const std::vector<std::size_t>& selected,
                              const std::vector<int>& columns);

// The distinct values (12 significant digits, increasing) of a column among the selected rows.
std::vector<double> distinct_values(const Rows& rows, const std::vector<std::size_t>& selected, int column);

}  // namespace cmp::fit
