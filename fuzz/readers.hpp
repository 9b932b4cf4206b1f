#pragma once
// The readers of lib/io as the fuzz targets and the corpus replay test call them: each takes
// the bytes of a whole file (read from memory, named "fuzz" in messages) and either reads them
// or throws cmp::InputError. Anything else escaping (another exception, a crash, a sanitizer
// report) is a bug.
#include <string>
#include <string_view>
#include <vector>

namespace cmp::fuzz {

struct Reader {
  const char* name;  // off, xyz, csv, vtk, packing (the fuzz target fuzz_<name>)
  void (*read)(const std::string& bytes);
};

// Every reader, in a fixed order.
const std::vector<Reader>& readers();
// The reader of that name; throws std::invalid_argument for an unknown one.
const Reader& reader(std::string_view name);

}  // namespace cmp::fuzz
