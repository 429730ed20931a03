#pragma once
// CRC-32 (IEEE 802.3, the polynomial and conventions of zlib's crc32, PNG and gzip) of a byte
// string: the checksum a checkpoint part carries (io::CheckpointStore). Written here, not taken
// from zlib, because nothing else in Glossa links zlib and 20 lines do not justify a dependency;
// being zlib's CRC, any tool checks it (`python3 -c "import zlib; ..."`). Chosen over a 64-bit
// hash because its guarantees fit the damage a file meets: every burst of up to 32 flipped bits
// and every 1- or 2-bit error in a part under 512 MB is detected, where a hash only makes a miss
// unlikely; any other change is missed with a probability of 2^-32.

#include <cstdint>
#include <string_view>

namespace glossa::io {

// The CRC of `bytes` continued from `crc` (the CRC of the bytes before them; 0 to start).
std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);

} // namespace glossa::io
