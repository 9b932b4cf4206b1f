#pragma once
// Extended XYZ files, one or many frames (a trajectory), as OVITO and ASE read them:
//   3
//   Lattice="10 0 0 0 10 0 0 0 10" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T" tool=x
//   X 0 0 0 0.5
//   ...
// Lattice holds a, b, c one after the other. Without Properties, ASE's default
// species:S:1:pos:R:3 applies; with a Lattice but no pbc, pbc is "T T T" (as in ASE).
#include "io/line_reader.hpp"
#include "io/xyz_frame.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace cmp::io {

// Reads frames one at a time, so a long trajectory need not fit in memory.
class XyzReader {
 public:
  // Opens path ("-" = stdin); throws cmp::InputError(path, 0, ...) when it cannot be read.
  explicit XyzReader(std::string path);
  // Reads an opened input (not owned; it must outlive the reader).
  explicit XyzReader(Input& input);
  // Reads the next frame into frame; false at the end of the file. Throws cmp::InputError with
  // file:line for: an atom count line that is not one integer >= 0, a truncated frame, a row
  // with the wrong number of fields, a non-number in an R or I column, a bad T/F, a Lattice
  // that is not 9 finite numbers, a pbc that is not 3 T/F flags, a bad Properties string,
  // Properties wider than a line can hold (kMaxLineBytes / 2 fields), more atoms than a
  // regular file has bytes for (2 per field); "empty file" when the file holds no frame at all.
  // Memory grows as rows arrive, whatever the count line claims.
  bool next(XyzFrame& frame);

 private:
  LineReader in_;
  int frames_ = 0;
};

// Every frame of the file (at least one). Throws as XyzReader::next.
std::vector<XyzFrame> read_xyz(const std::string& path);
std::vector<XyzFrame> read_xyz(Input& input);

// Appends frames to a stream (a trajectory). Every number is written in its shortest
// round-trip form, so a read gives back the same doubles.
class XyzWriter {
 public:
  explicit XyzWriter(std::ostream& out) : out_(out) {}
  // Writes one frame: count line, then Lattice="..." (when has_lattice) Properties=... pbc=...
  // and the info pairs, then one row per atom. Checks the whole frame before writing a byte:
  // throws std::invalid_argument for columns of unequal sizes, a string with whitespace in an S
  // column, a non-integer in an I column, a 0/1 other than in an L column, info keys that
  // clash with Lattice/Properties/pbc or are malformed; cmp::ComputationError for NaN/Inf in
  // an R column or the lattice.
  void write(const XyzFrame& frame);

 private:
  std::ostream& out_;
};

// Writes frames to path atomically (see AtomicOutput); "-" writes to stdout. Throws
// cmp::InputError(path, 0, ...) when the file cannot be written, else as XyzWriter::write.
void write_xyz(const std::string& path, const std::vector<XyzFrame>& frames);

}  // namespace cmp::io
