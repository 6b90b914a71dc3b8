#include "styk/inp/reader.hpp"

#include "deck_reader.hpp"

namespace styk {

Model read_inp(const std::string& path, const ElementRegistry& registry) {
  return inp::DeckReader(path, registry).read();
}

}  // namespace styk
