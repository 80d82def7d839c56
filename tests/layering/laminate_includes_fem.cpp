// Must not compile: the laminate layer cannot see fem headers (tests/CMakeLists.txt, Layering tests).
#include "plyimpact/fem/mesh.hpp"
