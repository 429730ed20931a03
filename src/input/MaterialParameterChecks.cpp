#include "input/MaterialParameterChecks.hpp"

#include "input/UnreadParameters.hpp"
#include "io/deck/DeckError.hpp"

namespace glossa::input {

namespace {
std::vector<std::string> pathTo(std::vector<std::string> path, const char *parameter) {
  path.emplace_back(parameter);
  return path;
}
} // namespace

void refuseOtherLawsParameters(const io::Deck &deck, const std::vector<std::string> &path) {
  // What buildTissue reads for each 'type' (MaterialFactory.cpp).
  static const std::vector<ReadUnder> readers{{"shear modulus", {"neo-Hookean"}},
                                              {"Fung A", {"Fung"}},
                                              {"Fung B", {"Fung"}},
                                              {"C10", {"Mooney-Rivlin", "Yeoh"}},
                                              {"C01", {"Mooney-Rivlin"}},
                                              {"C11", {"Mooney-Rivlin"}},
                                              {"C20", {"Mooney-Rivlin", "Yeoh"}},
                                              {"C02", {"Mooney-Rivlin"}},
                                              {"C30", {"Yeoh"}}};
  refuseUnreadParameters(deck, path, "type", readers);
}

void refuseOtherFieldsParameters(const io::Deck &deck, const std::vector<std::string> &path) {
  // What readFamily and readPointFamily read for each 'direction field' (MaterialFactory.cpp).
  static const std::vector<ReadUnder> readers{{"direction", {"constant"}},
                                              {"fan centre", {"radial fan"}},
                                              {"fan plane normal", {"radial fan"}},
                                              {"file", {"file"}},
                                              {"file gives", {"file"}},
                                              {"polylines", {"polylines"}},
                                              {"polyline sampling", {"polylines"}}};
  refuseUnreadParameters(deck, path, "direction field", readers);
}

bool bulkModulusGiven(const io::Deck &deck, const std::vector<std::string> &path) {
  const auto kappa = pathTo(path, "bulk modulus"), nu = pathTo(path, "Poisson's ratio");
  const Teuchos::ParameterList *section = &deck.root();
  for (const auto &p : path) section = &section->sublist(p);
  // 0 is the declared "from Poisson's ratio".
  const bool kappaPositive = section->get<double>("bulk modulus") > 0.0;
  if (!kappaPositive || !deck.given(kappa) || !deck.given(nu)) return kappaPositive;
  const bool kappaSet = deck.setOnCommandLine(kappa), nuSet = deck.setOnCommandLine(nu);
  if (kappaSet != nuSet) return kappaSet;
  throw io::DeckError(deck.where(kappa) + " and " + deck.where(nu) +
                      " are both given; the bulk modulus follows from one of them: give 'bulk modulus' (kappa) or "
                      "\"Poisson's ratio\" (nu, kappa = 2 mu (1+nu) / (3 (1-2nu))), not both");
}

} // namespace glossa::input
