#pragma once
// The deck's "time function" sublist (of a load, a boundary condition, a muscle group's input):
// its parameters, and the model::TimeFunction they describe.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::input {

Teuchos::ParameterList timeFunctionParameters(const std::string &defaultType = "ramp");
// `endTime` is the default ramp duration: the deck's own end time (the value its file gives,
// which --set "Time/end time=..." does not change), so a shortened run shows the first part of the
// deck's load history rather than the whole history compressed.
model::TimeFunction parseTimeFunction(const Teuchos::ParameterList &list, double endTime);
// The time function of the deck's sublist at `path`, its unread parameters refused; an
// inconsistent table is a DeckError there.
model::TimeFunction timeFunctionAt(const io::Deck &deck, const std::vector<std::string> &path, double endTime);
// Refuses (DeckError) a parameter the sublist at `path` gives that its type does not read (a
// ramp duration of a table, breathing parameters of a ramp).
void refuseUnreadTimeFunctionParameters(const io::Deck &deck, const std::vector<std::string> &path);

} // namespace glossa::input
