// CRC-32 against the published check value of the CRC catalogue (CRC-32/ISO-HDLC, zlib's and
// PNG's: "123456789" -> 0xCBF43926) and zlib's values for other strings, computed in one piece or
// continued across pieces; and every single-bit flip of a buffer changes it.
#include <string>

#include <gtest/gtest.h>

#include "io/output/Crc32.hpp"

namespace glossa::io {
namespace {

TEST(Crc32, MatchesThePublishedCheckValueAndZlib) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
  // python3 -c "import zlib; print(hex(zlib.crc32(b'The quick brown fox jumps over the lazy dog')))"
  EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
  EXPECT_EQ(crc32(std::string(4, '\0')), 0x2144DF1Cu); // leading zeros count
}

TEST(Crc32, ContinuesAcrossPieces) {
  const std::string text = "The quick brown fox jumps over the lazy dog";
  for (std::size_t cut = 0; cut <= text.size(); ++cut)
    EXPECT_EQ(crc32(text.substr(cut), crc32(text.substr(0, cut))), crc32(text)) << cut;
}

TEST(Crc32, EverySingleBitFlipChangesIt) {
  std::string bytes(300, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 37 + 11);
  const std::uint32_t clean = crc32(bytes);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string flipped = bytes;
      flipped[i] = static_cast<char>(flipped[i] ^ (1 << bit));
      ASSERT_NE(crc32(flipped), clean) << "byte " << i << " bit " << bit;
    }
}

} // namespace
} // namespace glossa::io
