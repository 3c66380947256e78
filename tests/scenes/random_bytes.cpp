// Writes SIZE pseudo-random bytes (xorshift64* from a fixed seed, so every run writes the same
// file) to PATH: hostile input for the scene reader in check_hostile_input.cmake.
//   random_bytes PATH SIZE
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: random_bytes PATH SIZE\n");
    return 2;
  }
  std::FILE* out = std::fopen(argv[1], "wb");
  if (out == nullptr) return 1;
  unsigned long long remaining = std::strtoull(argv[2], nullptr, 10);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  std::vector<unsigned char> block(1 << 16);
  while (remaining > 0) {
    const std::size_t n = remaining < block.size() ? static_cast<std::size_t>(remaining) : block.size();
    for (std::size_t i = 0; i < n; ++i) {
      state ^= state >> 12;
      state ^= state << 25;
      state ^= state >> 27;
      block[i] = static_cast<unsigned char>((state * 0x2545F4914F6CDD1Dull) >> 56);
    }
    if (std::fwrite(block.data(), 1, n, out) != n) return 1;
    remaining -= n;
  }
  return std::fclose(out) == 0 ? 0 : 1;
}
