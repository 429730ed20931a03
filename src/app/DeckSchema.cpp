#include "app/DeckSchema.hpp"

#include "model/SceneFactory.hpp"
#include "solvers/Simulation.hpp"

namespace glossa::app {

Teuchos::ParameterList deckSchema() {
  Teuchos::ParameterList schema("Glossa");
  model::declareSceneParameters(schema);
  solvers::declareSolverParameters(schema);
  return schema;
}

} // namespace glossa::app
