// ParaView collection files (see pvd.h).
#include "granlub/results/pvd.h"

#include <fmt/format.h>

namespace granlub {

std::string pvd_collection(const std::vector<PvdEntry>& entries) {
    std::string s = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <Collection>\n";
    for (const auto& e : entries)
        s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" file=\"{}\"/>\n", e.time, e.part, e.file);
    s += "  </Collection>\n</VTKFile>\n";
    return s;
}

}  // namespace granlub
