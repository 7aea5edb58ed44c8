// The one .pvd writer (granlub/results/pvd.h): the collection VTK writes, one DataSet per (time, part).
#include <boost/test/unit_test.hpp>

#include <string>

#include "granlub/results/pvd.h"

using namespace granlub;

BOOST_AUTO_TEST_CASE(pvd_lists_every_file_with_its_time_and_part) {
    const std::string s = pvd_collection({{0.002, 0, "particles_200.vtp"}, {0.002, 1, "box_200.vtr"}, {1e-5, 0, "a.vti"}});
    BOOST_TEST(s.starts_with("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\""));
    BOOST_TEST(s.find("<DataSet timestep=\"0.002\" group=\"\" part=\"0\" file=\"particles_200.vtp\"/>") != std::string::npos);
    BOOST_TEST(s.find("<DataSet timestep=\"0.002\" group=\"\" part=\"1\" file=\"box_200.vtr\"/>") != std::string::npos);
    BOOST_TEST(s.find("timestep=\"1e-05\"") != std::string::npos);  // shortest exact form
    BOOST_TEST(s.ends_with("  </Collection>\n</VTKFile>\n"));
    BOOST_TEST(pvd_collection({}).find("<Collection>\n  </Collection>") != std::string::npos);
}
