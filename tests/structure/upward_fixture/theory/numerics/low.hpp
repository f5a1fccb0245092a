#pragma once
// A planted upward include: check_layers.py must reject this tree (tests/CMakeLists.txt, WILL_FAIL).
#include "theory/grid/high.hpp"
