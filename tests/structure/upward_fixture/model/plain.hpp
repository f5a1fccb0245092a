#pragma once
// A planted upward include from model/ into theory/: also rejected.
#include "theory/grid/high.hpp"
