#include "io/csv.hpp"

#include "core/errors.hpp"
#include "io/input.hpp"
#include "io/line_reader.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_set>

namespace cmp::io {

namespace {

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

// Splits the record starting at the current line into fields (RFC 4180). A quoted field may
// run over several lines; the reader then advances past them.
std::vector<std::string> parse_record(LineReader& in) {
  const long start = in.line_number();
  std::vector<std::string> fields;
  std::string field;
  std::string line = in.line();
  std::size_t i = 0;
  while (true) {
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i == line.size()) {  // the quoted field holds a line break
          if (!in.next())
            throw InputError(in.path(), start, "unterminated quoted field (no closing '\"')");
          field += '\n';
          if (field.size() > kMaxLineBytes)
            throw InputError(in.path(), start,
                             fmt::format("quoted field longer than {} bytes (the line limit)",
                                         kMaxLineBytes));
          line = in.line();
          i = 0;
          continue;
        }
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += line[i++];
      }
      if (i < line.size() && line[i] != ',')
        in.fail(
            fmt::format("unexpected {} after a closing quote, expected ',' or the end of "
                        "the line",
                        quote_token(std::string_view(&line[i], 1))));
    } else {
      const auto end = std::min(line.find(',', i), line.size());
      field.assign(line, i, end - i);
      if (field.find('"') != std::string::npos)
        in.fail("a '\"' inside an unquoted field (quote the whole field and double the quote)");
      i = end;
    }
    fields.push_back(std::move(field));
    field.clear();
    if (i == line.size()) return fields;
    ++i;  // the comma
  }
}

bool needs_quotes(const std::string& cell) {
  return cell.find_first_of(",\"\n\r") != std::string::npos ||
         (!cell.empty() && (cell.front() == '#' || cell.front() == ' ' || cell.back() == ' '));
}

}  // namespace

const std::string* CsvTable::find_meta(const std::string& key) const {
  for (const auto& [k, v] : meta)
    if (k == key) return &v;
  return nullptr;
}

int CsvTable::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it != header.end()) return static_cast<int>(it - header.begin());
  std::string names;
  for (const auto& h : header) names += (names.empty() ? "'" : ", '") + h + "'";
  throw InputError(file, header_line, "no column '" + name + "'; the columns are " + names);
}

double CsvTable::number(std::size_t row, int column) const {
  if (row >= rows.size() || column < 0 || static_cast<std::size_t>(column) >= header.size())
    throw std::out_of_range(fmt::format("CsvTable::number({}, {}) outside a {} by {} table", row,
                                        column, rows.size(), header.size()));
  return parse_double(trim(rows[row][column]), file, row_lines[row],
                      "a number in column '" + header[column] + "'");
}

long long CsvTable::integer(std::size_t row, int column, long long lo, long long hi) const {
  if (row >= rows.size() || column < 0 || static_cast<std::size_t>(column) >= header.size())
    throw std::out_of_range(fmt::format("CsvTable::integer({}, {}) outside a {} by {} table", row,
                                        column, rows.size(), header.size()));
  return parse_integer(trim(rows[row][column]), file, row_lines[row],
                       "an integer in column " + quote_token(header[column]), lo, hi);
}

CsvTable read_csv(const std::string& path) {
  Input input(path);
  return read_csv(input);
}

CsvTable read_csv(Input& input) {
  LineReader in(input);
  const auto& path = in.path();
  CsvTable t;
  t.file = path;
  bool have_header = false;
  while (in.next()) {
    if (in.blank()) continue;
    if (in.comment()) {
      if (have_header) continue;  // a plain comment
      const auto& line = in.line();
      const auto text = std::string_view(line).substr(line.find('#') + 1);
      const auto eq = text.find('=');
      if (eq == std::string_view::npos) continue;
      auto key = trim(text.substr(0, eq));
      if (key.empty()) in.fail("'# =value' line without a key");
      t.meta.emplace_back(std::move(key), trim(text.substr(eq + 1)));
      continue;
    }
    const long line = in.line_number();
    auto fields = parse_record(in);
    if (!have_header) {
      std::unordered_set<std::string> seen;
      for (const auto& name : fields)
        if (!seen.insert(name).second)
          in.fail("column " + quote_token(name) + " appears twice in the header");
      t.header = std::move(fields);
      t.header_line = line;
      have_header = true;
      continue;
    }
    if (fields.size() != t.header.size())
      throw InputError(
          path, line,
          fmt::format("row has {} fields, the header has {}", fields.size(), t.header.size()));
    t.rows.push_back(std::move(fields));
    t.row_lines.push_back(line);
  }
  if (!have_header) in.fail_end("no header row");
  return t;
}

std::string csv_field(const std::string& cell) {
  if (!needs_quotes(cell)) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

void CsvWriter::meta(const std::string& key, const std::string& value) {
  if (has_header_) throw std::logic_error("CsvWriter::meta after the header");
  if (key.empty() || key.find_first_of("=#\n\r") != std::string::npos)
    throw std::invalid_argument("CsvWriter::meta: bad key '" + key + "'");
  std::string v = value;
  std::replace(v.begin(), v.end(), '\n', ' ');
  std::replace(v.begin(), v.end(), '\r', ' ');
  out_ << "# " << key << '=' << v << '\n';
}

void CsvWriter::header(const std::vector<std::string>& columns) {
  if (has_header_) throw std::logic_error("CsvWriter::header called twice");
  if (columns.empty()) throw std::invalid_argument("CsvWriter::header: no columns");
  width_ = columns.size();
  row(columns);
  has_header_ = true;
  columns_ = columns;
}

void CsvWriter::header_written_before(const std::vector<std::string>& columns) {
  if (has_header_) throw std::logic_error("CsvWriter::header called twice");
  if (columns.empty()) throw std::invalid_argument("CsvWriter::header: no columns");
  width_ = columns.size();
  has_header_ = true;
  columns_ = columns;
}

void CsvWriter::row(const std::vector<std::string>& cells) {
  if (width_ == 0) throw std::logic_error("CsvWriter::row before the header");
  if (cells.size() != width_)
    throw std::invalid_argument(
        fmt::format("CsvWriter::row: {} cells, the header has {}", cells.size(), width_));
  if (has_header_) {
    ++rows_;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto& c = cells[i];
      const bool nan = c == "nan" || c == "-nan", inf = c == "inf" || c == "-inf";
      if (nan || (inf && !infinity_allowed_))
        throw ComputationError(fmt::format("{} became {} (row {} of the table): a result file holds finite numbers only",
                                           columns_[i], c, rows_));
    }
  }
  // A one-column row holding "" would be a blank line, which readers skip.
  if (width_ == 1 && cells[0].empty()) {
    out_ << "\"\"\n";
    return;
  }
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) line += ',';
    line += csv_field(cells[i]);
  }
  line += '\n';
  out_ << line;
}

std::string format_number(double x) {
  return fmt::format("{}", x);
}

}  // namespace cmp::io
