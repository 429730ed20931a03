#include "io/output/Crc32.hpp"

#include <array>

namespace glossa::io {

namespace {
// The byte-wise table of the reflected polynomial 0xEDB88320 (x^32 + x^26 + ... + 1 read LSB first).
constexpr std::array<std::uint32_t, 256> table() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}
constexpr std::array<std::uint32_t, 256> kTable = table();
} // namespace

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) {
  // The register starts at and is read out through ~0, so leading zero bytes change the CRC.
  crc = ~crc;
  for (const char b : bytes) crc = kTable[(crc ^ static_cast<unsigned char>(b)) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

} // namespace glossa::io
