// ParaView collection for the VTK dumps (pvd.h), through core's one .pvd writer (granlub/results/pvd.h).
#include "pvd.h"

#include <algorithm>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "deck.h"
#include "granlub/error.h"
#include "granlub/results/pvd.h"
#include "granlub/results/results.h"

namespace granlub::dem {

namespace fs = std::filesystem;

std::vector<VtkFrame> vtk_frames(const fs::path& post_dir) {
    static const std::regex particles(R"(particles_([0-9]+)\.vtp)");
    static const std::regex box(R"(particles_boundingBox_([0-9]+)\.vtr)");
    std::map<long long, VtkFrame> frames;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(post_dir, ec)) {
        const std::string name = e.path().filename().string();
        std::smatch m;
        if (std::regex_match(name, m, particles)) {
            VtkFrame& f = frames[std::stoll(m[1].str())];
            f.step = std::stoll(m[1].str());
            f.particles = name;
        } else if (std::regex_match(name, m, box)) {
            frames[std::stoll(m[1].str())].box = name;
        }
    }
    std::vector<VtkFrame> out;
    for (auto& [step, f] : frames)
        if (!f.particles.empty()) out.push_back(f);  // a box without grains is not a frame
    return out;
}

std::string pvd_text(const std::vector<VtkFrame>& frames, double dt) {
    std::vector<PvdEntry> entries;
    for (const auto& f : frames) {
        const double t = static_cast<double>(f.step) * dt;
        entries.push_back({t, 0, f.particles});
        if (!f.box.empty()) entries.push_back({t, 1, f.box});
    }
    return pvd_collection(entries);
}

void write_pvd(const fs::path& dir, double dt) {
    const fs::path post = dir / "post";
    const auto frames = vtk_frames(post);
    if (frames.empty())
        throw SolverError(fmt::format("{}: --vtk was given but LIGGGHTS wrote no particles_<step>.vtp files",
                                      post.string()));
    write_file_atomic(dir / kPvdFile, pvd_text(frames, dt));
}

}  // namespace granlub::dem
