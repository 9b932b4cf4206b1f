#include "io/off.hpp"

#include "core/errors.hpp"
#include "io/atomic_output.hpp"
#include "io/input.hpp"
#include "io/line_reader.hpp"
#include "io/parse_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace cmp::io {

namespace {

// Geomview OFF allows a '#' comment at the end of any line; only the part before it counts.
std::vector<std::string_view> data_tokens(const std::string& line) {
  const auto hash = line.find('#');
  return split_whitespace(std::string_view(line).substr(0, hash));
}

// The words of a full-line comment after its '#', e.g. {"box", "1", "2", "3"}.
std::vector<std::string_view> comment_words(const std::string& line) {
  return split_whitespace(std::string_view(line).substr(line.find('#') + 1));
}

bool is_packing_keyword(std::string_view word) {
  return word == "box" || word == "periodic" || word == "shells";
}

// Parses the comment lines of a file: packing lines before the counts line, the rest kept.
class CommentParser {
 public:
  CommentParser(LineReader& in, OffFile& off) : in_(in), off_(off) {}

  void take(bool before_counts) {
    const auto words = comment_words(in_.line());
    if (words.empty() || !is_packing_keyword(words[0])) {
      std::string text = in_.line().substr(in_.line().find('#') + 1);
      if (!text.empty() && text[0] == ' ') text.erase(0, 1);
      off_.comments.push_back(std::move(text));
      off_.comment_lines.push_back(in_.line_number());
      return;
    }
    if (!before_counts)
      in_.fail("packing line '# " + std::string(words[0]) +
               "' must come before the counts line 'nV nF nE'");
    if (words[0] == "box") box(words);
    if (words[0] == "periodic") periodic(words);
    if (words[0] == "shells") shells(words);
  }

  long shells_line() const { return shells_line_; }
  // The '# shells' vertex counts added up in 64 bits (they may not fit an int).
  long long shell_vertex_sum() const { return shell_vertex_sum_; }

 private:
  void once(long& seen, std::string_view word) {
    if (seen)
      in_.fail("second '# " + std::string(word) + "' line (the first is line " +
               std::to_string(seen) + ")");
    seen = in_.line_number();
  }

  void box(const std::vector<std::string_view>& w) {
    once(box_line_, "box");
    if (w.size() != 4) in_.fail("expected '# box Lx Ly Lz' (three box sides)");
    Eigen::Vector3d L;
    for (int i = 0; i < 3; ++i) {
      L[i] = parse_double(w[i + 1], in_.path(), in_.line_number(), "a box side");
      if (!(L[i] > 0)) in_.fail("box side " + quote_token(w[i + 1]) + " is not positive");
      if (L[i] > kMaxCoordinate)
        in_.fail(fmt::format("box side {} is beyond {:g}: the volumes and distances made from it would overflow",
                             quote_token(w[i + 1]), kMaxCoordinate));
    }
    off_.packing.box = L;
    off_.packing.box_line = in_.line_number();
  }

  void periodic(const std::vector<std::string_view>& w) {
    once(periodic_line_, "periodic");
    if (w.size() != 4) in_.fail("expected '# periodic x y z' (three 0/1 flags)");
    for (int i = 0; i < 3; ++i) {
      if (w[i + 1] != "0" && w[i + 1] != "1")
        in_.fail("expected a periodic flag 0 or 1, got " + quote_token(w[i + 1]));
      off_.packing.periodic[i] = w[i + 1] == "1";
    }
  }

  void shells(const std::vector<std::string_view>& w) {
    once(shells_line_, "shells");
    if (w.size() < 2) in_.fail("expected '# shells K n1 ... nK'");
    const auto k = parse_integer(w[1], in_.path(), in_.line_number(), "the shell count K");
    if (k < 1) in_.fail("the shell count K must be positive, got " + quote_token(w[1]));
    if (static_cast<unsigned long long>(k) != w.size() - 2)
      in_.fail(fmt::format("'# shells {}' announces {} vertex counts, the line has {}", k, k,
                           w.size() - 2));
    auto& counts = off_.packing.shell_vertex_counts;
    for (long long i = 0; i < k; ++i) {
      const auto n = parse_integer(w[i + 2], in_.path(), in_.line_number(),
                                   "a shell vertex count", LLONG_MIN, INT_MAX);
      if (n < 1) in_.fail("shell vertex count must be positive, got " + quote_token(w[i + 2]));
      counts.push_back(static_cast<int>(n));
      shell_vertex_sum_ += n;  // at most 2^20 counts below 2^31: no overflow in 64 bits
    }
  }

  LineReader& in_;
  OffFile& off_;
  long box_line_ = 0, periodic_line_ = 0, shells_line_ = 0;
  long long shell_vertex_sum_ = 0;
};

// Reads up to the next line holding data, passing comment lines to the parser.
bool next_data(LineReader& in, CommentParser& comments, bool before_counts) {
  while (in.next()) {
    if (in.blank()) continue;
    if (in.comment()) {
      comments.take(before_counts);
      continue;
    }
    return true;
  }
  return false;
}

void check_packing(const mesh::VertexMatrix& V, const mesh::FaceMatrix& F, const PackingInfo& p) {
  if (p.box)
    for (int i = 0; i < 3; ++i)
      if (!((*p.box)[i] > 0) || !std::isfinite((*p.box)[i]))
        throw std::invalid_argument("write_off: box sides must be positive and finite");
  if (p.shell_vertex_counts.empty()) return;
  const auto offsets = shell_vertex_offsets(p);
  if (offsets.back() != V.rows())
    throw std::invalid_argument(
        fmt::format("write_off: shell vertex counts add up to {}, the mesh has {} vertices",
                    offsets.back(), V.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const auto shell = [&](int v) {
      return std::upper_bound(offsets.begin(), offsets.end(), v) - offsets.begin();
    };
    if (shell(F(f, 1)) != shell(F(f, 0)) || shell(F(f, 2)) != shell(F(f, 0)))
      throw std::invalid_argument(fmt::format("write_off: face {} spans two shells", f));
  }
}

}  // namespace

std::vector<int> shell_vertex_offsets(const PackingInfo& packing) {
  if (packing.shell_vertex_counts.empty()) return {};
  std::vector<int> offsets(packing.shell_vertex_counts.size() + 1, 0);
  std::partial_sum(packing.shell_vertex_counts.begin(), packing.shell_vertex_counts.end(),
                   offsets.begin() + 1);
  return offsets;
}

namespace {

// What the first word of an OFF file says: the Geomview prefixes [ST][C][N]OFF. Colours,
// normals and texture coordinates are read as numbers and dropped.
struct OffDialect {
  bool normals = false, colours = false, texture = false;
};

OffDialect parse_dialect(LineReader& in, std::string_view word) {
  OffDialect d;
  if (!word.ends_with("OFF")) in.fail("expected 'OFF' on the first line, got " + quote_token(word));
  auto prefix = word.substr(0, word.size() - 3);
  if (prefix.starts_with("ST")) d.texture = true, prefix.remove_prefix(2);
  if (prefix.starts_with("C")) d.colours = true, prefix.remove_prefix(1);
  if (prefix.starts_with("N")) d.normals = true, prefix.remove_prefix(1);
  if (!prefix.empty())
    in.fail("unsupported OFF variant " + quote_token(word) +
            ": OFF, COFF, NOFF, CNOFF and STOFF (3D, ASCII) are read");
  return d;
}

// Field counts a vertex line may have: x y z [nx ny nz] [r g b [a]] [s t].
bool vertex_fields_ok(const OffDialect& d, std::size_t n) {
  const std::size_t base = 3 + (d.normals ? 3 : 0) + (d.texture ? 2 : 0);
  return d.colours ? n == base + 3 || n == base + 4 : n == base;
}

std::string vertex_form(const OffDialect& d) {
  return fmt::format("x y z{}{}{}", d.normals ? " nx ny nz" : "", d.colours ? " r g b [a]" : "",
                     d.texture ? " s t" : "");
}

}  // namespace

OffFile read_off(const std::string& path) {
  Input input(path);
  return read_off(input);
}

OffFile read_off(Input& input) {
  LineReader in(input);
  OffFile off;
  CommentParser comments(in, off);
  if (!next_data(in, comments, true)) in.fail_end("expected the 'OFF' line");
  auto tokens = data_tokens(in.line());
  if (tokens.empty()) in.fail("expected 'OFF' on the first line");
  const auto dialect = parse_dialect(in, tokens[0]);
  // The counts may follow "OFF" on the same line ("OFF 8 12 0") or have a line of their own.
  tokens.erase(tokens.begin());
  if (tokens.size() == 1 && tokens[0] == "BINARY")
    in.fail("binary OFF ('OFF BINARY') is not supported: write it as ASCII");
  if (tokens.empty()) {
    if (!next_data(in, comments, true)) in.fail_end("expected the counts line 'nV nF nE'");
    tokens = data_tokens(in.line());
  }
  if (tokens.size() != 3)
    in.fail(fmt::format("expected the counts 'nV nF nE', got {} fields", tokens.size()));
  const auto& file = in.path();
  const long line = in.line_number();
  const int nv =
      static_cast<int>(parse_integer(tokens[0], file, line, "the vertex count", 0, INT_MAX));
  const int nf =
      static_cast<int>(parse_integer(tokens[1], file, line, "the face count", 0, INT_MAX));
  parse_integer(tokens[2], file, line, "the edge count", 0);

  if (comments.shells_line() && comments.shell_vertex_sum() != nv)
    throw InputError(file, comments.shells_line(),
                     fmt::format("'# shells' vertex counts add up to {}, but the file has {} "
                                 "vertices",
                                 comments.shell_vertex_sum(), nv));
  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8 ("3 0 1 2\n").
  const auto least = 6ULL * static_cast<unsigned long long>(nv) + 8ULL * static_cast<unsigned>(nf);
  // A claim past the end of a regular file is refused at once when it is large (no reading
  // megabytes to find out); a small one is read and reported where the file ends.
  if (const auto left = input.bytes_left(); left && least > *left && least > kMaxLineBytes)
    in.fail(fmt::format("the counts line claims {} vertices and {} faces, at least {} bytes; "
                        "the file has {} bytes left",
                        nv, nf, least, *left));
  const auto offsets = shell_vertex_offsets(off.packing);

  // Grow as lines arrive rather than trusting the counts line with a huge allocation.
  constexpr int kReserve = 1 << 16;
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(std::min(nv, kReserve)));
  for (int i = 0; i < nv; ++i) {
    if (!next_data(in, comments, false))
      in.fail_end(fmt::format("expected {} vertices, got {}", nv, i));
    tokens = data_tokens(in.line());
    if (!vertex_fields_ok(dialect, tokens.size()))
      in.fail(fmt::format("expected a vertex '{}', got {} fields", vertex_form(dialect),
                          tokens.size()));
    for (std::size_t k = 0; k < 3; ++k) {
      xyz.push_back(parse_double(tokens[k], file, in.line_number(), "a coordinate"));
      if (std::abs(xyz.back()) > kMaxCoordinate)
        in.fail(fmt::format("coordinate {} is beyond +-{:g}: the distances, areas and volumes made from it would "
                            "overflow", quote_token(tokens[k]), kMaxCoordinate));
    }
    for (std::size_t k = 3; k < tokens.size(); ++k)
      parse_double(tokens[k], file, in.line_number(), "a number (normal, colour or texture)");
  }
  std::vector<int> ijk;
  ijk.reserve(3 * static_cast<std::size_t>(std::min(nf, kReserve)));
  const auto shell = [&](int v) {
    return std::upper_bound(offsets.begin(), offsets.end(), v) - offsets.begin();
  };
  for (int f = 0; f < nf; ++f) {
    if (!next_data(in, comments, false))
      in.fail_end(fmt::format("expected {} faces, got {}", nf, f));
    tokens = data_tokens(in.line());
    const int n = parse_int(tokens[0], file, in.line_number(), "the face's vertex count");
    if (n != 3)
      in.fail(
          fmt::format("face with {} vertices: triangles are required (triangulate the "
                      "mesh first)",
                      n));
    // "3 i j k", or with a colour as MeshLab writes it: "3 i j k r g b [a]".
    if (tokens.size() != 4 && tokens.size() != 7 && tokens.size() != 8)
      in.fail(fmt::format("expected a face '3 i j k' or '3 i j k r g b [a]', got {} fields",
                          tokens.size()));
    if (nv == 0) in.fail("face in a file without vertices");
    int v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = static_cast<int>(
          parse_integer(tokens[k + 1], file, in.line_number(), "a vertex index", 0, nv - 1));
      ijk.push_back(v[k]);
    }
    for (std::size_t k = 4; k < tokens.size(); ++k)
      parse_double(tokens[k], file, in.line_number(), "a colour component");
    if (!offsets.empty() && (shell(v[1]) != shell(v[0]) || shell(v[2]) != shell(v[0])))
      in.fail(
          fmt::format("face {} {} {} uses vertices of shells {}, {} and {}: each shell's "
                      "faces must use only its own vertices",
                      v[0], v[1], v[2], shell(v[0]), shell(v[1]), shell(v[2])));
  }
  if (next_data(in, comments, false))
    in.fail(
        fmt::format("more records than announced: the counts line says {} vertices and "
                    "{} faces",
                    nv, nf));

  off.V = Eigen::Map<const mesh::VertexMatrix>(xyz.data(), nv, 3);
  off.F = Eigen::Map<const mesh::FaceMatrix>(ijk.data(), nf, 3);
  return off;
}

void write_off(std::ostream& out, const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
               const std::vector<std::string>& comments, const PackingInfo* packing) {
  const auto nv = V.rows();
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= nv)
        throw std::invalid_argument(fmt::format(
            "write_off: face {} has vertex index {}, the mesh has {} vertices", f, F(f, k), nv));
  if (!V.allFinite()) throw ComputationError("write_off: a vertex coordinate is NaN or infinite");
  if (packing) check_packing(V, F, *packing);

  fmt::memory_buffer buf;
  const auto flush = [&] {
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    buf.clear();
  };
  fmt::format_to(std::back_inserter(buf), "OFF\n");
  for (auto text : comments) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    const auto words = split_whitespace(text);
    if (!words.empty() && is_packing_keyword(words[0]))
      throw std::invalid_argument("write_off: comment '" + text +
                                  "' would read back as a packing line");
    fmt::format_to(std::back_inserter(buf), "# {}\n", text);
  }
  if (packing) {
    if (packing->box)
      fmt::format_to(std::back_inserter(buf), "# box {} {} {}\n", (*packing->box)[0],
                     (*packing->box)[1], (*packing->box)[2]);
    const auto& p = packing->periodic;
    fmt::format_to(std::back_inserter(buf), "# periodic {} {} {}\n", int(p[0]), int(p[1]),
                   int(p[2]));
    if (!packing->shell_vertex_counts.empty())
      fmt::format_to(std::back_inserter(buf), "# shells {} {}\n",
                     packing->shell_vertex_counts.size(),
                     fmt::join(packing->shell_vertex_counts, " "));
  }
  fmt::format_to(std::back_inserter(buf), "{} {} 0\n", nv, F.rows());
  constexpr std::size_t kChunk = 1 << 16;
  for (Eigen::Index i = 0; i < nv; ++i) {
    fmt::format_to(std::back_inserter(buf), "{} {} {}\n", V(i, 0), V(i, 1), V(i, 2));
    if (buf.size() > kChunk) flush();
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    fmt::format_to(std::back_inserter(buf), "3 {} {} {}\n", F(f, 0), F(f, 1), F(f, 2));
    if (buf.size() > kChunk) flush();
  }
  flush();
}

void write_off(const std::string& path, const mesh::VertexMatrix& V, const mesh::FaceMatrix& F,
               const std::vector<std::string>& comments, const PackingInfo* packing) {
  AtomicOutput out(path);
  write_off(out.stream(), V, F, comments, packing);
  out.commit();
}

}  // namespace cmp::io
