#include "input/DeckSets.hpp"

#include "io/deck/DeckError.hpp"

namespace glossa::input {

// The scene is the model layer's; this layer only reads it from the deck.
using namespace glossa::model;

namespace {
template <class Map> std::string namesOf(const Map &sets) {
  std::string s;
  for (const auto &entry : sets) s += (s.empty() ? "" : ", ") + entry.first;
  return s.empty() ? "(none)" : s;
}
} // namespace

const std::string &deckString(const io::Deck &deck, const std::vector<std::string> &path) {
  const Teuchos::ParameterList *list = &deck.root();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) list = &list->sublist(path[i]);
  return list->get<std::string>(path.back());
}

std::vector<mesh::ElementId> elementSetOrAll(const io::Deck &deck, const mesh::HexMesh &m,
                                             const std::vector<std::string> &path) {
  const std::string &set = deckString(deck, path);
  if (set.empty()) {
    std::vector<mesh::ElementId> all(m.numElements());
    for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<mesh::ElementId>(e);
    return all;
  }
  if (!m.elementSets.count(set))
    throw io::DeckError(deck.where(path) + ": no element set '" + set + "'; the mesh has: " + namesOf(m.elementSets));
  // A tissue or fibre family of no element would be dropped without a word.
  if (m.elementSets.at(set).empty())
    throw io::DeckError(deck.where(path) + ": element set '" + set + "' has no elements");
  return m.elementSets.at(set);
}

const std::vector<mesh::ElementFace> &faceSetAt(const io::Deck &deck, const mesh::HexMesh &m,
                                                const std::vector<std::string> &path) {
  const std::string &set = deckString(deck, path);
  if (!m.faceSets.count(set))
    throw io::DeckError(deck.where(path) + ": no face set '" + set + "'; the mesh has: " + namesOf(m.faceSets));
  return m.faceSets.at(set);
}

const std::vector<mesh::NodeId> &nodeSetAt(const io::Deck &deck, const mesh::HexMesh &m,
                                           const std::vector<std::string> &path) {
  const std::string &set = deckString(deck, path);
  if (!m.nodeSets.count(set))
    throw io::DeckError(deck.where(path) + ": no node set '" + set + "'; the mesh has: " + namesOf(m.nodeSets));
  return m.nodeSets.at(set);
}

int muscleGroupAt(const io::Deck &deck, const MuscleArchitecture &muscles, const std::vector<std::string> &path,
                  bool required) {
  const std::string &name = deckString(deck, path);
  if (name.empty() && !required) return -1;
  const int g = muscles.groupIndex(name);
  if (g >= 0) return g;
  std::string known;
  for (const auto &group : muscles.groups) known += (known.empty() ? "" : ", ") + group.name;
  throw io::DeckError(deck.where(path) + ": no muscle group '" + name + "' in Material/Muscle groups (" +
                      (known.empty() ? "none declared" : known) + ")");
}

} // namespace glossa::input
