#include "flowrun/checkpoint_file.hpp"

#include "core/errors.hpp"
#include "io/atomic_output.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>

namespace cmp::flowrun {

namespace {

constexpr const char* kMagic = "lbflow checkpoint 1";

// Reads the header; leaves `in` at the first byte of the solver state.
std::vector<std::string> read_header(std::istream& in, const std::string& path) {
  std::string line;
  long number = 1;
  if (!std::getline(in, line) || line != kMagic)
    throw InputError(path, 1, fmt::format("not an lbflow checkpoint (expected '{}' on the first line)", kMagic));
  std::size_t n = 0;
  ++number;
  if (!(in >> line >> n) || line != "args" || n > 10000)
    throw InputError(path, number, "expected 'args <count>' in the checkpoint header");
  std::vector<std::string> args;
  for (std::size_t k = 0; k < n; ++k) {
    ++number;
    std::size_t length = 0;
    if (!(in >> length) || length > (1u << 20) || in.get() != ' ')
      throw InputError(path, number, "expected '<length> <argument>' in the checkpoint header");
    std::string arg(length, '\0');
    if (!in.read(arg.data(), static_cast<std::streamsize>(length)))
      throw InputError(path, number, "truncated checkpoint header");
    args.push_back(std::move(arg));
  }
  in.ignore(1);  // the line break after the last argument (or after the count)
  if (!std::getline(in, line) || line != "state")
    throw InputError(path, number + 1, "expected 'state' after the arguments of the checkpoint");
  return args;
}

std::ifstream open(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the checkpoint");
  return in;
}

}  // namespace

void write_checkpoint(const std::string& path, const std::vector<std::string>& args, const lbm::FlowSolver& solver,
                      const std::vector<lbm::FlowObservables>& history) {
  io::AtomicOutput out(path);
  auto& s = out.stream();
  s << kMagic << "\nargs " << args.size() << '\n';
  for (const auto& a : args) s << a.size() << ' ' << a << '\n';
  s << "state\n";
  solver.save(s, history);
  out.commit();
}

std::vector<std::string> read_checkpoint_args(const std::string& path) {
  auto in = open(path);
  return read_header(in, path);
}

std::vector<lbm::FlowObservables> load_checkpoint(const std::string& path, lbm::FlowSolver& solver) {
  auto in = open(path);
  read_header(in, path);
  return solver.load(in, path);
}

}  // namespace cmp::flowrun
