// `granlub dem --vtk`: LIGGGHTS' VTK XML dumps plus a ParaView collection (.pvd) listing every
// frame with its simulated time; the .pvd is well-formed and names only files that exist.
#define BOOST_TEST_MODULE liggghts_dem_vtk
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"
#include "granlub/error.h"
#include "granlub/results/results.h"
#include "granlub/run/sweep.h"
#include "pvd.h"
#include "tiny_cell.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

const std::string kCase = test::tiny_cell("tiny_vtk", "", "time = 0.01\nsample_every = 20\nsnapshots = 5\nstations = 6\n");

std::string read(const fs::path& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path scratch(const std::string& name) { return test::scratch("liggghts_dem_vtk", name); }

}  // namespace

BOOST_AUTO_TEST_CASE(frames_are_sorted_by_step_and_paired_with_their_box) {
    const fs::path d = scratch("frames");
    for (const char* f : {"particles_1000.vtp", "particles_200.vtp", "particles_0.vtp", "particles_boundingBox_200.vtr",
                          "particles_boundingBox_0.vtr", "particles_boundingBox_1000.vtr", "particles_boundingBox_7.vtr",
                          "notes.txt", "particles_x.vtp"})
        std::ofstream(d / f) << "x";
    const auto frames = dem::vtk_frames(d);
    BOOST_TEST_REQUIRE(frames.size() == 3u);  // a box without grains and foreign files are not frames
    BOOST_TEST(frames[0].step == 0);
    BOOST_TEST(frames[1].step == 200);
    BOOST_TEST(frames[2].step == 1000);
    BOOST_TEST(frames[1].particles == "particles_200.vtp");
    BOOST_TEST(frames[1].box == "particles_boundingBox_200.vtr");
    const std::string pvd = dem::pvd_text(frames, 1e-5);
    BOOST_TEST(pvd.find("<VTKFile type=\"Collection\"") != std::string::npos);
    BOOST_TEST(pvd.find("timestep=\"0.002\" group=\"\" part=\"0\" file=\"particles_200.vtp\"") != std::string::npos);
    BOOST_TEST(pvd.find("timestep=\"0.01\" group=\"\" part=\"1\" file=\"particles_boundingBox_1000.vtr\"") !=
               std::string::npos);
    BOOST_TEST(pvd.rfind("</VTKFile>\n") == pvd.size() - 11);
    // no frames: a clear error, no file
    const fs::path empty = scratch("empty");
    fs::create_directories(empty / "post");
    BOOST_CHECK_THROW(dem::write_pvd(empty, 1e-5), SolverError);
    BOOST_TEST(!fs::exists(empty / "post" / "particles.pvd"));
}

BOOST_AUTO_TEST_CASE(vtk_run_writes_a_pvd_naming_every_dump) {
    const Case c = parse_case(kCase, "tiny_vtk.toml", test::dem_schema());
    RunOptions o;
    o.results_root = scratch("run");
    o.vtk = true;
    BOOST_TEST_REQUIRE(dem::run(c, o) == 0);
    const fs::path post = result_dir(o.results_root, "dem", c.points.front().id) / "post";
    const std::string pvd = read(post / "particles.pvd");
    BOOST_TEST_REQUIRE(!pvd.empty());
    std::size_t vtp = 0;
    for (const auto& e : fs::directory_iterator(post))
        if (e.path().extension() == ".vtp") ++vtp;
    static const std::regex file(R"re(part="0" file="([^"]+)")re");
    std::size_t listed = 0;
    for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file); it != std::sregex_iterator(); ++it) {
        ++listed;
        BOOST_TEST(fs::exists(post / (*it)[1].str()), (*it)[1].str());
    }
    BOOST_TEST(vtp >= 5u);
    BOOST_TEST(listed == vtp);
    // the dumps are VTK XML PolyData with the grains
    const std::string first = read(post / "particles_0.vtp");
    BOOST_TEST(first.find("<VTKFile type=\"PolyData\"") != std::string::npos);
    BOOST_TEST(first.find("NumberOfPoints=\"220\"") != std::string::npos);
}
