// The contact-law table (granlub/particles/contact_laws.h): each engine's laws, in the order the
// case keys list them, the rows each engine needs filled, and a clear failure for a name not there.
#include <set>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/particles/contact_laws.h"

using namespace granlub;

BOOST_AUTO_TEST_CASE(each_engine_lists_its_laws) {
    BOOST_TEST(contact_law_names(ParticleEngine::Liggghts) == (std::vector<std::string>{"impulse", "hertz"}),
               boost::test_tools::per_element());
    BOOST_TEST(contact_law_names(ParticleEngine::Yade) == (std::vector<std::string>{"viscel", "hertz"}),
               boost::test_tools::per_element());
    const std::string doc = contact_law_doc(ParticleEngine::Yade);
    BOOST_TEST(doc.find("viscel = ") == 0u);
    BOOST_TEST(doc.find("; hertz = ") != std::string::npos);
    BOOST_TEST(doc.find("impulse =") == std::string::npos);  // not a YADE law
}

BOOST_AUTO_TEST_CASE(rows_are_complete_and_names_unique) {
    std::set<std::string> names;
    for (const ContactLaw& l : contact_laws()) {
        BOOST_TEST(names.insert(l.name).second);
        BOOST_TEST(std::string(l.title).size() > 0u);
        BOOST_TEST((l.liggghts || l.yade), l.name << " is in no engine");
        // the impulse options are the rigid operator's: a law with springs has none
        BOOST_TEST(l.impulse_options == (l.stiffness == Stiffness::Rigid), l.name);
        // a rigid law's step follows the travel per step; a spring's from its stiffness
        BOOST_TEST((l.step == StepRule::Travel) == (l.stiffness == Stiffness::Rigid), l.name);
        // the report words the rigid operator's line itself (it depends on contact_solve)
        BOOST_TEST((l.contacts == nullptr) == l.impulse_options, l.name);
    }
    BOOST_TEST(std::string(contact_law("hertz").liggghts) == "model hertz tangential history");
    BOOST_TEST(std::string(contact_law("impulse").liggghts) == "model impulse tangential impulse");
    BOOST_TEST(contact_law("impulse").yade == nullptr);
}

BOOST_AUTO_TEST_CASE(an_unknown_law_is_named_in_the_error) {
    BOOST_TEST(find_contact_law("hooke") == nullptr);
    try {
        (void)contact_law("hooke");
        BOOST_FAIL("no error");
    } catch (const Error& e) {
        BOOST_TEST(std::string(e.what()).find("'hooke'") != std::string::npos);
    }
}
