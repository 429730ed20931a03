#pragma once
// Writes doc/deck-reference.md from the schema the objects declare, so the reference can never
// drift from what the code validates.

#include <ostream>

#include <Teuchos_ParameterList.hpp>

namespace glossa::io {

void writeDeckReference(const Teuchos::ParameterList &schema, std::ostream &out);

} // namespace glossa::io
