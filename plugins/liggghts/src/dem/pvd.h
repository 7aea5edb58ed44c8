// ParaView collection (.pvd) for the LIGGGHTS VTK dump series of a point (--vtk).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace granlub::dem {

struct VtkFrame {
    long long step = 0;
    std::string particles;  // file name relative to post/, e.g. particles_100.vtp
    std::string box;        // the matching bounding box (particles_boundingBox_100.vtr), or empty
};

// The frames of `post_dir` (particles_<step>.vtp and particles_boundingBox_<step>.vtr), by step.
std::vector<VtkFrame> vtk_frames(const std::filesystem::path& post_dir);

// The .pvd text: one DataSet per frame with timestep = step * dt (s); grains are part 0, the box part 1.
std::string pvd_text(const std::vector<VtkFrame>& frames, double dt);

// Writes <dir>/post/particles.pvd atomically (core's write_file_atomic). Throws SolverError when
// LIGGGHTS wrote no frames.
void write_pvd(const std::filesystem::path& dir, double dt);

}  // namespace granlub::dem
