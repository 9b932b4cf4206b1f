#pragma once
// Shared helpers of the voxel tests: random images and a plain flood-fill labelling to check
// label_components against (numbered in the same memory order, so labels compare equal).
#include "core/random.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cmp::voxel::fixtures {

inline std::vector<std::uint8_t> random_image(std::array<int, 3> d, double p_void, std::uint64_t seed) {
  cmp::Random r(seed);
  std::vector<std::uint8_t> img(static_cast<std::size_t>(d[0]) * d[1] * d[2]);
  for (auto& v : img) v = r.uniform() < p_void;
  return img;
}

// Breadth-first flood fill with an explicit neighbour list: slow, obviously right.
inline int flood_fill_labels(const std::vector<std::uint8_t>& img, std::array<int, 3> d, int connectivity,
                             std::array<bool, 3> periodic, std::vector<int>& labels) {
  std::vector<std::array<int, 3>> offsets;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int n1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (n1 == 0 || (connectivity == 6 && n1 > 1) || (connectivity == 18 && n1 > 2)) continue;
        offsets.push_back({dx, dy, dz});
      }
  labels.assign(img.size(), 0);
  int count = 0;
  std::vector<long> stack;
  auto idx = [&](int x, int y, int z) { return x + static_cast<long>(d[0]) * (y + static_cast<long>(d[1]) * z); };
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) {
        if (!img[idx(x, y, z)] || labels[idx(x, y, z)]) continue;
        labels[idx(x, y, z)] = ++count;
        stack.push_back(idx(x, y, z));
        while (!stack.empty()) {
          const long i = stack.back();
          stack.pop_back();
          const int p[3] = {static_cast<int>(i % d[0]), static_cast<int>((i / d[0]) % d[1]),
                            static_cast<int>(i / (static_cast<long>(d[0]) * d[1]))};
          for (const auto& o : offsets) {
            int q[3];
            bool ok = true;
            for (int a = 0; a < 3; ++a) {
              q[a] = p[a] + o[a];
              if (q[a] < 0 || q[a] >= d[a]) {
                if (!periodic[a]) ok = false;
                q[a] = (q[a] + d[a]) % d[a];
              }
            }
            if (!ok) continue;
            const long j = idx(q[0], q[1], q[2]);
            if (img[j] && !labels[j]) {
              labels[j] = count;
              stack.push_back(j);
            }
          }
        }
      }
  return count;
}

}  // namespace cmp::voxel::fixtures
