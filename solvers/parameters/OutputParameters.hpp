#pragma once
// The deck's Output section, declared and parsed once: where results go, how often fields and
// checkpoints are written, and the face sets whose resultants and volumes are recorded.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

struct OutputParameters {
  std::string directory; // relative to the working directory; parseRunConfiguration: results/<deck stem> if empty
  int every = 1;
  bool fields = true;
  std::vector<std::string> resultantFaceSets, volumeFaceSets;
  int checkpointEvery = 10; // 0: never
};

Teuchos::ParameterList outputParameters();
OutputParameters parseOutputParameters(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
