#pragma once
#include <vector>

#include "granlub/schema.h"

namespace granlub {
std::vector<SectionSpec> common_sections();
}
