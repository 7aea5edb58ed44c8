// A fresh folder under the system temp folder for one test process, removed at the end of the scope.
#pragma once
#include <filesystem>
#include <string>

#include <unistd.h>

namespace granlub::continuum::testing {

struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name = "continuum") {
        path = std::filesystem::temp_directory_path() / ("granlub_" + name + "_test_" + std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace granlub::continuum::testing
