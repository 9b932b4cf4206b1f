#pragma once
// 64-bit FNV-1a over bytes: the fingerprint a checkpoint carries of the inputs of its run, so
// that a resume with other inputs is refused (not a cryptographic hash).
#include <cstddef>
#include <cstdint>

namespace cmp {

struct Fnv1a {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

}  // namespace cmp
