// Fixture for the include-rule test: map/ including core/ is allowed.
#pragma once
#include "core/point.hpp"
