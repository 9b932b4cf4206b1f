#include "io/xyz.hpp"

#include "core/errors.hpp"
#include "io/atomic_output.hpp"
#include "io/input.hpp"
#include "io/key_value_line.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <unordered_set>

namespace cmp::io {

namespace {

// A logical as ASE and OVITO write it; false when token is none.
bool parse_flag(std::string_view token, bool& out) {
  if (token == "T" || token == "True" || token == "true" || token == "1") return out = true, true;
  if (token == "F" || token == "False" || token == "false" || token == "0")
    return out = false, true;
  return false;
}

std::vector<XyzColumn> parse_properties(const std::string& text, LineReader& in) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto colon = text.find(':', start);
    parts.push_back(text.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() % 3 != 0)
    in.fail("Properties must be name:type:width triples, got " + quote_token(text));
  std::vector<XyzColumn> columns;
  std::unordered_set<std::string> names;
  for (std::size_t i = 0; i < parts.size(); i += 3) {
    XyzColumn c;
    c.name = parts[i];
    if (c.name.empty()) in.fail("Properties: empty column name in " + quote_token(text));
    if (!names.insert(c.name).second)
      in.fail("Properties: column " + quote_token(c.name) + " appears twice");
    if (parts[i + 1].size() != 1 ||
        std::string_view("RISL").find(parts[i + 1][0]) == std::string_view::npos)
      in.fail("Properties: column " + quote_token(c.name) + " has type " +
              quote_token(parts[i + 1]) + ", expected R, I, S or L");
    c.type = parts[i + 1][0];
    c.width = static_cast<int>(parse_integer(parts[i + 2], in.path(), in.line_number(),
                                             "a column width in Properties", 1, 1 << 20));
    columns.push_back(std::move(c));
  }
  return columns;
}

// Reads the comment line into frame: Lattice, pbc, Properties (returned) and info.
std::vector<XyzColumn> parse_comment(LineReader& in, XyzFrame& frame) {
  const auto& text = in.line();
  KeyValues pairs;
  try {
    pairs = parse_key_values(text, in.path(), in.line_number());
  } catch (const InputError&) {
    // A plain XYZ title with a stray quote is no key=value line; keep it whole. A line that
    // means to be extended XYZ must parse, though.
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    if (lower.find("properties=") != std::string::npos ||
        lower.find("lattice=") != std::string::npos)
      throw;
    pairs = {{"comment", text}};
  }
  std::string properties = "species:S:1:pos:R:3";
  bool has_pbc = false;
  for (auto& [key, value] : pairs) {
    if (same_key(key, "Lattice")) {
      auto numbers = value;
      std::replace(numbers.begin(), numbers.end(), ',', ' ');
      const auto tokens = split_whitespace(numbers);
      if (tokens.size() != 9)
        in.fail(fmt::format("Lattice must hold 9 numbers (a, b, c), got {}", tokens.size()));
      for (int k = 0; k < 9; ++k)
        frame.lattice(k / 3, k % 3) =
            parse_double(tokens[k], in.path(), in.line_number(), "a number in Lattice");
      frame.has_lattice = true;
    } else if (same_key(key, "pbc")) {
      const auto tokens = split_whitespace(value);
      bool ok = tokens.size() == 3;
      for (std::size_t k = 0; ok && k < 3; ++k) ok = parse_flag(tokens[k], frame.pbc[k]);
      if (!ok) in.fail("pbc must be 3 flags T or F, got " + quote_token(value));
      has_pbc = true;
    } else if (same_key(key, "Properties")) {
      properties = value;
    } else {
      frame.info.emplace_back(std::move(key), std::move(value));
    }
  }
  if (frame.has_lattice && !has_pbc) frame.pbc = {true, true, true};
  return parse_properties(properties, in);
}

void parse_row(LineReader& in, std::vector<XyzColumn>& columns, int total_width,
               const std::string& properties_text) {
  const auto& tokens = in.tokens();
  if (static_cast<int>(tokens.size()) != total_width)
    in.fail(fmt::format("expected {} fields ({}), got {}", total_width, properties_text,
                        tokens.size()));
  std::size_t t = 0;
  for (auto& c : columns) {
    for (int k = 0; k < c.width; ++k, ++t) {
      const auto token = tokens[t];
      switch (c.type) {
        case 'S':
          c.strings.emplace_back(token);
          break;
        case 'R':
          c.values.push_back(parse_double(token, in.path(), in.line_number(),
                                          "a number in column '" + c.name + "'"));
          break;
        case 'I': {
          constexpr long long kExact = 1LL << 53;  // stored as double
          c.values.push_back(static_cast<double>(
              parse_integer(token, in.path(), in.line_number(),
                            "an integer in column '" + c.name + "'", -kExact, kExact)));
          break;
        }
        default: {
          bool flag = false;
          if (!parse_flag(token, flag))
            in.fail("expected T or F in column '" + c.name + "', got " + quote_token(token));
          c.values.push_back(flag ? 1.0 : 0.0);
        }
      }
    }
  }
}

std::string properties_string(const std::vector<XyzColumn>& columns) {
  std::string out;
  for (const auto& c : columns)
    out += fmt::format("{}{}:{}:{}", out.empty() ? "" : ":", c.name, c.type, c.width);
  return out;
}

void check_frame(const XyzFrame& frame) {
  const int n = frame.size();
  if (frame.columns.empty())
    throw std::invalid_argument("write_xyz: a frame needs at least one column (Properties)");
  for (const auto& c : frame.columns) {
    if (c.name.empty() || c.name.find_first_of(": \t\r\n\"'") != std::string::npos)
      throw std::invalid_argument("write_xyz: bad column name '" + c.name + "'");
    if (c.width <= 0 || std::string_view("RISL").find(c.type) == std::string_view::npos)
      throw std::invalid_argument("write_xyz: column '" + c.name + "' has a bad type or width");
    const auto stored = c.type == 'S' ? c.strings.size() : c.values.size();
    if (stored != static_cast<std::size_t>(n) * c.width)
      throw std::invalid_argument(
          fmt::format("write_xyz: column '{}' holds {} values, expected "
                      "{} atoms x {}",
                      c.name, stored, n, c.width));
    for (const auto& s : c.strings)
      if (s.empty() || s.find_first_of(" \t\r\n\v\f") != std::string::npos)
        throw std::invalid_argument("write_xyz: string '" + s + "' in column '" + c.name +
                                    "' is empty or holds whitespace");
    for (double v : c.values) {
      if (c.type == 'R' && !std::isfinite(v))
        throw ComputationError("write_xyz: column '" + c.name + "' holds NaN or Inf");
      if (c.type == 'I' && (!std::isfinite(v) || v != std::trunc(v) || std::abs(v) > 0x1p53))
        throw std::invalid_argument(
            fmt::format("write_xyz: column '{}' holds {}, not an integer", c.name, v));
      if (c.type == 'L' && v != 0 && v != 1)
        throw std::invalid_argument(
            fmt::format("write_xyz: column '{}' holds {}, not 0/1", c.name, v));
    }
  }
  if (frame.has_lattice && !frame.lattice.allFinite())
    throw ComputationError("write_xyz: the lattice holds NaN or Inf");
  for (const auto& [key, value] : frame.info) {
    if (same_key(key, "Lattice") || same_key(key, "Properties") || same_key(key, "pbc"))
      throw std::invalid_argument("write_xyz: info key '" + key + "' is reserved");
    format_key_value(key, value);  // throws on a malformed key
  }
}

}  // namespace

XyzReader::XyzReader(std::string path) : in_(std::move(path)) {}

XyzReader::XyzReader(Input& input) : in_(input) {}

bool XyzReader::next(XyzFrame& frame) {
  frame = XyzFrame{};
  // Blank lines between frames and at the end are tolerated.
  do {
    if (!in_.next()) {
      if (frames_ == 0) in_.fail_end("expected the number of atoms");
      return false;
    }
  } while (in_.blank());
  const auto& tokens = in_.tokens();
  if (tokens.size() != 1)
    in_.fail("expected the number of atoms (one integer) to start a frame, got " +
             quote_token(in_.line()));
  const int n = static_cast<int>(
      parse_integer(tokens[0], in_.path(), in_.line_number(), "the number of atoms", 0, INT_MAX));
  frame.file = in_.path();
  frame.line = in_.line_number();
  if (!in_.next())
    in_.fail_end(fmt::format("expected the comment line of the frame at line {}", frame.line));
  auto columns = parse_comment(in_, frame);
  const auto properties_text = properties_string(columns);
  // Every field of a row takes at least 2 bytes (a character and a separator): the row width
  // must fit a line, and a regular file must hold the rows the count line claims.
  long long width = 0;
  for (const auto& c : columns) width += c.width;  // at most 2^20 columns of 2^20: no overflow
  if (width > static_cast<long long>(kMaxLineBytes / 2))
    in_.fail(fmt::format("Properties ask for {} fields per atom, more than a line of at most {} "
                         "bytes holds",
                         width, kMaxLineBytes));
  const int total_width = static_cast<int>(width);
  const auto least = 2ULL * static_cast<unsigned long long>(width) * static_cast<unsigned>(n);
  // A claim past the end of a regular file is refused at once when it is large (no reading
  // megabytes to find out); a small one is read and reported where the file ends.
  if (const auto left = in_.input().bytes_left(); left && least > *left && least > kMaxLineBytes)
    throw InputError(in_.path(), frame.line,
                     fmt::format("the frame claims {} atoms of {} fields, at least {} bytes; the "
                                 "file has {} bytes left",
                                 n, width, least, *left));
  // Grow as rows arrive rather than trusting the count line with a huge allocation.
  constexpr std::size_t kReserve = 1 << 16;
  for (auto& c : columns) {
    const auto reserve =
        std::min(static_cast<std::size_t>(n) * static_cast<std::size_t>(c.width), kReserve);
    if (c.type == 'S')
      c.strings.reserve(reserve);
    else
      c.values.reserve(reserve);
  }
  for (int i = 0; i < n; ++i) {
    if (!in_.next())
      in_.fail_end(
          fmt::format("expected {} atoms in the frame at line {}, got {}", n, frame.line, i));
    parse_row(in_, columns, total_width, properties_text);
  }
  frame.columns = std::move(columns);
  ++frames_;
  return true;
}

std::vector<XyzFrame> read_xyz(const std::string& path) {
  Input input(path);
  return read_xyz(input);
}

std::vector<XyzFrame> read_xyz(Input& input) {
  XyzReader reader(input);
  std::vector<XyzFrame> frames;
  XyzFrame frame;
  while (reader.next(frame)) frames.push_back(std::move(frame));
  return frames;
}

void XyzWriter::write(const XyzFrame& frame) {
  check_frame(frame);
  fmt::memory_buffer buf;
  auto it = std::back_inserter(buf);
  const int n = frame.size();
  fmt::format_to(it, "{}\n", n);
  if (frame.has_lattice) {
    const auto& L = frame.lattice;
    fmt::format_to(it, "Lattice=\"{} {} {} {} {} {} {} {} {}\" ", L(0, 0), L(0, 1), L(0, 2),
                   L(1, 0), L(1, 1), L(1, 2), L(2, 0), L(2, 1), L(2, 2));
  }
  const auto tf = [](bool b) { return b ? 'T' : 'F'; };
  fmt::format_to(it, "Properties={} pbc=\"{} {} {}\"", properties_string(frame.columns),
                 tf(frame.pbc[0]), tf(frame.pbc[1]), tf(frame.pbc[2]));
  for (const auto& [key, value] : frame.info)
    fmt::format_to(it, " {}", format_key_value(key, value));
  buf.push_back('\n');
  for (int i = 0; i < n; ++i) {
    bool first = true;
    for (const auto& c : frame.columns) {
      for (int k = 0; k < c.width; ++k) {
        if (!first) buf.push_back(' ');
        first = false;
        const std::size_t j = static_cast<std::size_t>(i) * c.width + k;
        switch (c.type) {
          case 'S':
            fmt::format_to(it, "{}", c.strings[j]);
            break;
          case 'R':
            fmt::format_to(it, "{}", c.values[j]);
            break;
          case 'I':
            fmt::format_to(it, "{}", static_cast<long long>(c.values[j]));
            break;
          default:
            buf.push_back(c.values[j] != 0 ? 'T' : 'F');
        }
      }
    }
    buf.push_back('\n');
    if (buf.size() > (1 << 16)) {
      out_.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out_.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

void write_xyz(const std::string& path, const std::vector<XyzFrame>& frames) {
  AtomicOutput out(path);
  XyzWriter writer(out.stream());
  for (const auto& f : frames) writer.write(f);
  out.commit();
}

}  // namespace cmp::io
