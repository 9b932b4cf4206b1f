#include "io/checkpoint_file.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cmp::io {

void write_checkpoint_header(std::ostream& s, const std::string& magic, const std::vector<std::string>& args) {
  s << magic << "\nargs " << args.size() << '\n';
  for (const auto& a : args) s << a.size() << ' ' << a << '\n';
  s << "state\n";
}

namespace {
constexpr const char* kChecksumState = "state fnv1a64";
constexpr std::size_t kTrailerBytes = 26;  // "\nfnv1a64 " + 16 hex digits + "\n"

std::string trailer(std::uint64_t h) { return fmt::format("\nfnv1a64 {:016x}\n", h); }

// Hashes the state (from the stream's position to the trailer) and compares it with the
// trailer; leaves the stream where it was.
void verify_checksum(std::istream& in, const std::string& path) {
  const auto damaged = [&](const std::string& why) { return InputError(path, 0, "checkpoint damaged: " + why); };
  const auto start = in.tellg();
  if (start < 0 || !in.seekg(0, std::ios::end)) throw damaged("cannot read it twice (not a regular file)");
  const auto end = in.tellg();
  if (end - start < static_cast<std::streamoff>(kTrailerBytes)) throw damaged("it is cut short (no checksum at its end)");
  const auto state_end = end - static_cast<std::streamoff>(kTrailerBytes);
  in.seekg(state_end);
  std::string tail(kTrailerBytes, '\0');
  if (!in.read(tail.data(), static_cast<std::streamsize>(kTrailerBytes))) throw damaged("unreadable checksum");
  in.seekg(start);
  Fnv1a h;
  char chunk[1 << 16];
  for (std::streamoff left = state_end - start; left > 0;) {
    const auto n = std::min<std::streamoff>(left, sizeof chunk);
    if (!in.read(chunk, static_cast<std::streamsize>(n))) throw damaged("it is cut short");
    h.bytes(chunk, static_cast<std::size_t>(n));
    left -= n;
  }
  if (tail != trailer(h.h))
    throw damaged("its contents do not match its checksum (a changed or cut file): start the run again");
  in.seekg(start);
}
}  // namespace

CheckpointOutput::CheckpointOutput(const std::string& path, const std::string& magic,
                                   const std::vector<std::string>& args)
    : out_(path), stream_(&buffer_) {
  auto& s = out_.stream();
  s << magic << "\nargs " << args.size() << '\n';
  for (const auto& a : args) s << a.size() << ' ' << a << '\n';
  s << kChecksumState << '\n';
  buffer_.attach(s.rdbuf());
}

CheckpointOutput::~CheckpointOutput() = default;

void CheckpointOutput::commit() {
  stream_.flush();
  out_.stream() << trailer(buffer_.hash.h);
  out_.commit();
}

CheckpointOutput::HashingBuffer::int_type CheckpointOutput::HashingBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  hash.bytes(&ch, 1);
  return target_->sputc(ch);
}

std::streamsize CheckpointOutput::HashingBuffer::xsputn(const char* s, std::streamsize n) {
  hash.bytes(s, static_cast<std::size_t>(n));
  return target_->sputn(s, n);
}

std::vector<std::string> read_checkpoint_header(std::istream& in, const std::string& path, const std::string& magic,
                                                const std::string& what, bool require_checksum) {
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
  if (!std::getline(in, line) || (line != "state" && line != kChecksumState))
    throw InputError(path, number + 1, "expected 'state' after the arguments of the checkpoint");
  if (line == kChecksumState) verify_checksum(in, path);
  else if (require_checksum) throw InputError(path, number + 1, "checkpoint damaged: it has no checksum");
  return args;
}

std::ifstream open_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the checkpoint");
  return in;
}

}  // namespace cmp::io
