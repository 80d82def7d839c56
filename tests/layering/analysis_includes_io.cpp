// Must not compile: the analysis layer cannot see io headers (tests/CMakeLists.txt, Layering tests).
#include "plyimpact/io/deck/deck.hpp"
