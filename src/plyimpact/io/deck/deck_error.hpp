#pragma once
#include <stdexcept>

namespace plyimpact {

/// A deck that cannot be used. what() reads "FILE:LINE:COLUMN: error: ..." naming what was expected.
class DeckError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace plyimpact
