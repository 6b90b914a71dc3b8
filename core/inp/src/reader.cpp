#include "styk/inp/reader.hpp"

#include "deck_reader.hpp"

namespace styk {

Model read_inp(const std::string& path, const ElementRegistry& registry,
               DeckCompleteness completeness) {
  return inp::DeckReader(path, registry, completeness).read();
}

}  // namespace styk
