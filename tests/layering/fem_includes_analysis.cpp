// Must not compile: the fem layer cannot see analysis headers (tests/CMakeLists.txt, Layering tests).
#include "plyimpact/analysis/contact/contact_rules.hpp"
