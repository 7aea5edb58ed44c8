#pragma once
#include <vector>

#include "granlub/case/schema.h"

namespace granlub {
std::vector<SectionSpec> common_sections();
}
