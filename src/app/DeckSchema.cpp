#include "app/DeckSchema.hpp"

#include "input/PointParameters.hpp"
#include "input/SceneFactory.hpp"
#include "input/ZeroStrainParameters.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::app {

Teuchos::ParameterList deckSchema() {
  Teuchos::ParameterList schema("Glossa");
  input::declareSceneParameters(schema);
  solvers::declareSolverParameters(schema);
  schema.set("Point", input::pointParameters(), "the deformation path of glossa point (one material point)");
  schema.set("Zero strain", input::zeroStrainParameters(),
             "glossa zero-strain: the zero-strain configuration under the deck's gravity (§8.1)");
  return schema;
}

} // namespace glossa::app
