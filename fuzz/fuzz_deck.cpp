// libFuzzer target: the deck parser (TOML text → Deck) must either return a Deck or throw DeckError
// with a located message. Any other exception, crash, hang, leak or undefined behaviour is a finding.
#include "plyimpact/io/deck/deck.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const plyimpact::Deck deck = plyimpact::parse_deck(text, "fuzz.toml");
    (void)deck;
  } catch (const plyimpact::DeckError&) {
    // the expected outcome for bad input: a message with file:line:column
  }
  return 0;
}
