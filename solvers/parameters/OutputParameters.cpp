#include "solvers/parameters/OutputParameters.hpp"

#include "io/deck/NameList.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList outputParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, "directory", "",
                    "where results go, relative to the working directory (the deck's other paths are relative "
                    "to the deck); empty: results/<the deck file's name without .xml>; glossa run --output "
                    "overrides");
  io::declareInt(p, "every", 1, "write fields every this many converged steps (the last always)",
                 io::Range::atLeast(1));
  io::declareBool(p, "fields", true, "write HDF5/XDMF fields (traces and summary are always written)");
  io::declareString(p, "resultant face sets", "",
                    "face sets whose resultant force goes to resultants.csv every step: the sum over the set's "
                    "nodes of internal less body forces, i.e. a support's reaction or a load's resultant "
                    "(comma separated)");
  io::declareInt(p, "checkpoint every", 10,
                 "write the state to <directory>/checkpoint every this many converged steps (and when a signal "
                 "stops the run), for glossa run --restart; 0: never",
                 io::Range::atLeast(0));
  io::declareString(p, "volume face sets", "",
                    "face sets whose enclosed volume goes to volumes.csv every step: 1/3 of the integral of "
                    "x . n over the deformed faces (n the body's outward normal), the body's volume for its "
                    "whole boundary, minus a cavity's for the cavity's wall (comma separated)");
  return p;
}

OutputParameters parseOutputParameters(const Teuchos::ParameterList &s) {
  OutputParameters p;
  p.directory = s.get<std::string>("directory");
  p.every = s.get<int>("every");
  p.fields = s.get<bool>("fields");
  p.resultantFaceSets = io::splitNameList(s.get<std::string>("resultant face sets"));
  p.volumeFaceSets = io::splitNameList(s.get<std::string>("volume face sets"));
  p.checkpointEvery = s.get<int>("checkpoint every");
  return p;
}

} // namespace glossa::solvers
