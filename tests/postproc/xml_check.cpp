#include "xml_check.h"

#include <expat.h>

#include <string>

namespace granlub::test {

std::string xml_error(const std::string& text) {
    XML_Parser p = XML_ParserCreate("UTF-8");
    std::string err;
    if (XML_Parse(p, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_ERROR)
        err = "line " + std::to_string(XML_GetCurrentLineNumber(p)) + ": " + XML_ErrorString(XML_GetErrorCode(p));
    XML_ParserFree(p);
    return err;
}

}  // namespace granlub::test
