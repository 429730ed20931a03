#pragma once
// The validator attached to every declared parameter: it knows the parameter's kind, unit,
// numeric range or allowed words, and explains a bad value in words a deck author can act on.

#include <string>
#include <vector>

#include <Teuchos_ParameterEntryValidator.hpp>

#include "io/deck/ParameterSpec.hpp"

namespace glossa::io {

class SpecValidator : public Teuchos::ParameterEntryValidator {
public:
  enum class Kind { Double, Int, Bool, String, DoubleArray, IntArray };

  SpecValidator(Kind kind, std::string unit, Range range, std::vector<std::string> allowed,
                int arraySize);

  Kind kind() const { return kind_; }
  const std::string &unit() const { return unit_; }
  // "" if the entry is acceptable, otherwise why not.
  std::string check(const Teuchos::ParameterEntry &entry) const;
  // "" unless `v`, read from the deck's `text`, is a finite bound of the range that the text is
  // not: "0.49999999999999999999" becomes the double 0.5 and so passes a range that allows 0.5
  // (and means something particular there, exact incompressibility for Poisson's ratio), though
  // the author meant a number below it. Otherwise why it is refused.
  std::string checkText(double v, const std::string &text) const;
  // What is allowed, in words: "real number, 0 < value [Pa]", "one of: cg, gmres".
  std::string allowed() const;
  // Parses a command-line string into a value of this kind (for --set), as strictly as the XML
  // deck's values (io/deck/StrictNumber.hpp); throws std::invalid_argument with the reason.
  Teuchos::ParameterEntry parse(const std::string &text) const;

  const std::string getXMLTypeName() const override { return "GlossaSpecValidator"; }
  void printDoc(const std::string &docString, std::ostream &out) const override;
  ValidStringsList validStringValues() const override;
  void validate(const Teuchos::ParameterEntry &entry, const std::string &paramName,
                const std::string &sublistName) const override;

private:
  Kind kind_;
  std::string unit_;
  Range range_;
  std::vector<std::string> allowedWords_;
  int arraySize_; // 0: any size
};

} // namespace glossa::io
