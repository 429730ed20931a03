#pragma once
// The whole deck schema: every section declared by the object that owns it.

#include <Teuchos_ParameterList.hpp>

namespace glossa::app {

Teuchos::ParameterList deckSchema();

} // namespace glossa::app
