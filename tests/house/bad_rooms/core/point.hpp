// Fixture for the include-rule test: core/ (the lowest room) including map/ must be refused.
#pragma once
#include "map/lanelet.hpp"
