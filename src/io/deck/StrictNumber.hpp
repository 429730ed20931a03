#pragma once
// Reading numbers from deck text, strictly: the whole text must be one number of the declared
// kind, finite and representable. `strtod`-style readers stop at the first character they do not
// understand and silently change a value ("0,4999" -> 0, "3.5abc" -> 3.5, "2 3" -> 2,
// "0x10" -> 16, "" -> 0, "1e999" -> inf); these refuse them. One reader for the XML deck and for
// --set, so a value means the same wherever it is written. Each function throws
// std::invalid_argument whose message says, in words, what is wrong with the text.

#include <string>
#include <vector>

namespace glossa::io {

// A decimal number: optional sign, digits with an optional fraction (or a fraction alone), an
// optional exponent ("1e-3", "-.5", "2.", "+7E+02"). Surrounding blanks are allowed; inf, nan,
// hexadecimal and values beyond the range of a double are not.
double parseStrictDouble(const std::string &text);
// Whether two decimal texts (as parseStrictDouble accepts them) denote exactly the same number:
// "0.5", "+.50" and "5e-1" do, "0.49999999999999999999" and "0.5" do not (though both read as
// the double 0.5).
bool sameDecimalValue(const std::string &a, const std::string &b);
// Decimal digits with an optional sign, within the range of int.
int parseStrictInt(const std::string &text);
// true or false (also 1 or 0, as Teuchos writes them in some versions).
bool parseStrictBool(const std::string &text);
// "{a, b, c}" (braces optional on the command line, where `bracesRequired` is false): entries
// separated by commas, none empty; "{}" is the empty array.
std::vector<double> parseStrictDoubleArray(const std::string &text, bool bracesRequired);
std::vector<int> parseStrictIntArray(const std::string &text, bool bracesRequired);

} // namespace glossa::io
