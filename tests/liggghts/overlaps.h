// Overlaps of a LIGGGHTS dump's last frame (columns id x y z radius): what the enduring-contact
// tests (resting bed, growing packing) measure. Periods of 0 mean a non-periodic axis.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "run_driver.h"

namespace granlub::test {

struct Grain {
    double x, y, z, r;
};

struct Overlaps {
    std::size_t grains = 0, contacts = 0, floor_contacts = 0;
    std::size_t touching = 0;    // pairs closer than 1 % of r_i + r_j (overlapping or not)
    double max = 0, median = 0;  // grain-grain, relative to r_i + r_j
    double floor_max = 0;        // grain-floor (z = 0), relative to r
    double top = 0;              // highest centre
};

inline std::vector<Grain> last_frame(const std::filesystem::path& dump) {
    const std::string text = read_text(dump);
    std::istringstream in(text.substr(text.rfind("ITEM: ATOMS")));
    std::string header;
    std::getline(in, header);
    std::vector<Grain> g;
    long id;
    Grain a;
    while (in >> id >> a.x >> a.y >> a.z >> a.r) g.push_back(a);
    return g;
}

// `floor`: a wall at z = 0 (the resting bed); periods of the x, y, z axes (0 = not periodic).
inline Overlaps measure(const std::vector<Grain>& g, std::array<double, 3> period, bool floor) {
    const auto wrap = [](double d, double p) { return p > 0 ? d - p * std::round(d / p) : d; };
    Overlaps o;
    o.grains = g.size();
    std::vector<double> rel;
    for (std::size_t i = 0; i < g.size(); ++i) {
        o.top = std::max(o.top, g[i].z);
        if (floor && g[i].z < g[i].r) {
            ++o.floor_contacts;
            o.floor_max = std::max(o.floor_max, (g[i].r - g[i].z) / g[i].r);
        }
        for (std::size_t j = i + 1; j < g.size(); ++j) {
            const double dx = wrap(g[i].x - g[j].x, period[0]), dy = wrap(g[i].y - g[j].y, period[1]),
                         dz = wrap(g[i].z - g[j].z, period[2]), sum = g[i].r + g[j].r;
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            if (d < sum) rel.push_back((sum - d) / sum);
            if (d < 1.01 * sum) ++o.touching;
        }
    }
    o.contacts = rel.size();
    if (!rel.empty()) {
        std::sort(rel.begin(), rel.end());
        o.max = rel.back();
        o.median = rel.size() % 2 ? rel[rel.size() / 2] : 0.5 * (rel[rel.size() / 2 - 1] + rel[rel.size() / 2]);
    }
    return o;
}

}  // namespace granlub::test
