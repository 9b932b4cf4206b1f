#include "io/checkpoint_file.hpp"

#include <fmt/format.h>

namespace cmp::io {

void write_checkpoint_header(std::ostream& s, const std::string& magic, const std::vector<std::string>& args) {
  s << magic << "\nargs " << args.size() << '\n';
  for (const auto& a : args) s << a.size() << ' ' << a << '\n';
  s << "state\n";
}

std::vector<std::string> read_checkpoint_header(std::istream& in, const std::string& path, const std::string& magic,
                                                const std::string& what) {
  std::string line;
  long number = 1;
  if (!std::getline(in, line) || line != magic)
    throw InputError(path, 1, fmt::format("not {} (expected '{}' on the first line)", what, magic));
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

std::ifstream open_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the checkpoint");
  return in;
}

}  // namespace cmp::io
