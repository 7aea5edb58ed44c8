// Test helpers: the tiny test case (tests/yade/tiny/case.toml), with [yade] lines replaced or
// added, parsed with the common sections plus [yade].
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/yade/command.h"

namespace granlub::yade::test {

inline std::filesystem::path tiny_case_file() {
    return std::filesystem::path(GRANLUB_SOURCE_DIR) / "tests" / "yade" / "tiny" / "case.toml";
}

inline std::string tiny_case_text() {
    std::ifstream in(tiny_case_file());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline Schema yade_schema() {
    Schema s = Schema::common();
    s.add(section());
    return s;
}

// The tiny case with `replace` substituted for `what` (both whole text snippets) and `extra`
// appended to [yade] (the last section of the file).
inline Case tiny_case(const std::string& what = "", const std::string& replace = "", const std::string& extra = "") {
    std::string text = tiny_case_text();
    if (!what.empty()) {
        const auto at = text.find(what);
        if (at == std::string::npos) throw std::runtime_error("test case has no '" + what + "'");
        text.replace(at, what.size(), replace);
    }
    text += extra;
    Case c = parse_case(text, tiny_case_file().string(), yade_schema());
    c.dir = tiny_case_file().parent_path();
    c.file = tiny_case_file();
    return c;
}

// The tiny case with several whole-snippet substitutions and `extra` appended to [yade].
inline Case tiny_case_edits(const std::vector<std::pair<std::string, std::string>>& edits, const std::string& extra) {
    std::string text = tiny_case_text();
    for (const auto& [what, replace] : edits) {
        const auto at = text.find(what);
        if (at == std::string::npos) throw std::runtime_error("test case has no '" + what + "'");
        text.replace(at, what.size(), replace);
    }
    Case c = parse_case(text + extra, tiny_case_file().string(), yade_schema());
    c.dir = tiny_case_file().parent_path();
    c.file = tiny_case_file();
    return c;
}

// A fresh, empty folder under the build tree.
inline std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "yade-scratch" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Sets an environment variable for the scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old, had_ = true;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (had_) ::setenv(name_, old_.c_str(), 1);
        else ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::string old_;
    bool had_ = false;
};

inline std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace granlub::yade::test
