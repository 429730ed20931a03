// Deck numbers are read strictly: every text a strtod-style reader would silently change is
// refused with a reason (the cases a hostile deck author found), and every plain number reads
// back exactly as a C++ literal of the same text.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "io/deck/StrictNumber.hpp"

using namespace glossa::io;

namespace {
std::string reasonOf(double (*parse)(const std::string &), const std::string &text) {
  try {
    parse(text);
  } catch (const std::invalid_argument &e) {
    return e.what();
  }
  return "";
}
} // namespace

TEST(StrictNumber, PlainDecimalsReadAsTheirLiterals) {
  EXPECT_EQ(parseStrictDouble("0.4999"), 0.4999);
  EXPECT_EQ(parseStrictDouble("-.5"), -0.5);
  EXPECT_EQ(parseStrictDouble("2."), 2.0);
  EXPECT_EQ(parseStrictDouble("+7E+02"), 700.0);
  EXPECT_EQ(parseStrictDouble("1e-3"), 1e-3);
  EXPECT_EQ(parseStrictDouble(" 15e9 "), 15e9); // blanks around the number are not part of it
  EXPECT_EQ(parseStrictDouble("1.7976931348623157e308"), std::numeric_limits<double>::max());
  EXPECT_EQ(parseStrictDouble("1e-400"), 0.0); // below the smallest denormal: the nearest double
  EXPECT_EQ(parseStrictInt("-42"), -42);
  EXPECT_EQ(parseStrictInt("2147483647"), 2147483647);
}

// Equal as decimals, not merely as doubles: what tells a bound written out from a longer text
// that rounds to it (Deck, "ATextReadAsTheBoundItIsNotIsRefused").
TEST(StrictNumber, SameDecimalValueComparesTheTextsNotTheirDoubles) {
  for (const char *half : {"0.5", "+0.5", ".5", "0.50", "5e-1", "0.005E+2", "50.0e-2", " 0.5 "})
    EXPECT_TRUE(sameDecimalValue(half, "0.5")) << half;
  for (const char *zero : {"0", "-0", "0.000", "0e7", ".0"}) EXPECT_TRUE(sameDecimalValue(zero, "0")) << zero;
  EXPECT_TRUE(sameDecimalValue("1e-06", "0.000001"));
  EXPECT_TRUE(sameDecimalValue("120", "1.2e2"));
  EXPECT_EQ(parseStrictDouble("0.49999999999999999999"), 0.5); // the same double ...
  EXPECT_FALSE(sameDecimalValue("0.49999999999999999999", "0.5")); // ... but not the same number
  EXPECT_FALSE(sameDecimalValue("-0.5", "0.5"));
  EXPECT_FALSE(sameDecimalValue("0.5", "5"));
  EXPECT_FALSE(sameDecimalValue("1e-400", "0"));
  EXPECT_FALSE(sameDecimalValue("0.51", "0.5"));
}

TEST(StrictNumber, RefusesWhatStrtodWouldSilentlyChange) {
  for (const char *text : {"0,4999", "3.5abc", "2 3", "0x10", "eighty", "{}", "inf", "-inf", "nan", "1e", "e5", ".",
                           "+", "1.2.3", "1e5.5", "--1", "0.3 Pa"})
    EXPECT_NE(reasonOf(parseStrictDouble, text).find("is not a number"), std::string::npos) << text;
  EXPECT_NE(reasonOf(parseStrictDouble, "").find("empty"), std::string::npos);
  EXPECT_NE(reasonOf(parseStrictDouble, "   ").find("empty"), std::string::npos);
  EXPECT_NE(reasonOf(parseStrictDouble, "1e999").find("beyond the range of a double"), std::string::npos);
  EXPECT_NE(reasonOf(parseStrictDouble, "-1e999").find("beyond the range of a double"), std::string::npos);
  EXPECT_THROW(parseStrictInt("4.5"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt("1e3"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt("0x10"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt("1e308"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt("2147483648"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt("99999999999999999999999"), std::invalid_argument);
  EXPECT_THROW(parseStrictInt(""), std::invalid_argument);
  EXPECT_TRUE(parseStrictBool("true"));
  EXPECT_FALSE(parseStrictBool("0"));
  EXPECT_THROW(parseStrictBool("yes"), std::invalid_argument);
  EXPECT_THROW(parseStrictBool("True"), std::invalid_argument);
}

TEST(StrictNumber, ArraysRefuseOneBadEntryInsteadOfZeroingTheArray) {
  EXPECT_EQ(parseStrictDoubleArray("{0, -9.81, 0}", true), (std::vector<double>{0.0, -9.81, 0.0}));
  EXPECT_EQ(parseStrictDoubleArray("{}", true), std::vector<double>{});
  EXPECT_EQ(parseStrictDoubleArray("16,16,16", false), (std::vector<double>{16, 16, 16}));
  EXPECT_EQ(parseStrictIntArray("{ 4,4 , 4 }", true), (std::vector<int>{4, 4, 4}));
  for (const char *text : {"{0, abc, 0}", "{nan,0,0}", "{0,-inf,0}", "{1,2 3,4}"}) {
    try {
      parseStrictDoubleArray(text, true);
      ADD_FAILURE() << text << " was accepted";
    } catch (const std::invalid_argument &e) {
      EXPECT_NE(std::string(e.what()).find("entry"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parseStrictDoubleArray("{-1,-1, }", true), std::invalid_argument); // an empty last entry
  EXPECT_THROW(parseStrictDoubleArray("{,1}", true), std::invalid_argument);
  EXPECT_THROW(parseStrictDoubleArray("{1,,2}", true), std::invalid_argument);
  EXPECT_THROW(parseStrictDoubleArray("1, 2, 3", true), std::invalid_argument); // the deck writes braces
  EXPECT_THROW(parseStrictDoubleArray("{1, 2", false), std::invalid_argument);
  EXPECT_THROW(parseStrictIntArray("{4.5,4,4}", true), std::invalid_argument);
  EXPECT_THROW(parseStrictIntArray("{1e308,2,2}", true), std::invalid_argument);
}
