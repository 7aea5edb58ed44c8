// ParaView collection for the VTK dumps (pvd.h). Format: VTK's XML "Collection" file
// (https://www.paraview.org/Wiki/ParaView/Data_formats#PVD_File_Format).
#include "pvd.h"

#include <algorithm>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "deck.h"
#include "granlub/error.h"
#include "granlub/results.h"

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
    std::string s = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <Collection>\n";
    for (const auto& f : frames) {
        const double t = static_cast<double>(f.step) * dt;
        s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, f.particles);
        if (!f.box.empty())
            s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"1\" file=\"{}\"/>\n", t, f.box);
    }
    s += "  </Collection>\n</VTKFile>\n";
    return s;
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
