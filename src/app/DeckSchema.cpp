#include "app/DeckSchema.hpp"

#include "app/PointCommand.hpp"
#include "model/SceneFactory.hpp"
#include "solvers/Simulation.hpp"

namespace glossa::app {

Teuchos::ParameterList deckSchema() {
  Teuchos::ParameterList schema("Glossa");
  model::declareSceneParameters(schema);
  solvers::declareSolverParameters(schema);
  schema.set("Point", pointParameters(), "the deformation path of glossa point (one material point)");
  return schema;
}

} // namespace glossa::app
