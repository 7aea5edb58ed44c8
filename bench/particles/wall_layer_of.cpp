// run.wall_layer (core wall_layer.h) of a finished particle point, from the files it left: the
// record the pipeline now writes, for results reduced before it did. Reads only.
//   wall_layer_of <point folder> <cell length, m> <depth, m> [trough]
// <depth>: the periodic depth the engines ran ([particles] periodic_depth, or 10 grain diameters),
// or with `trough` the cell's width (side walls). The walls' bumps are laid out again by core's
// wall_bumps.h from the summary's inputs (grain diameter, roughness) and run.walls (bump diameter),
// and must match run.walls' counts.
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/particles/particles.h"
#include "granlub/particles/wall_layer.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

std::optional<BumpLayer> bumps(const nlohmann::json& summary, const char* side, const ParticleBox& box) {
    const nlohmann::json& w = summary.at("run").at("walls").at(side);
    if (w.at("surface") != "bumps") return std::nullopt;
    Case c;
    c.grains.diameter = summary.at("inputs").at("diameter").get<double>();
    c.cell.length = box.length;
    Wall wall;
    wall.surface = WallSurface::Bumps;
    wall.roughness = summary.at("inputs").at(std::string("roughness_") + side).get<double>();
    wall.bump_diameter = w.at("bump_diameter_m").get<double>();
    OperatingPoint p;
    p.id = summary.at("point").get<std::string>();
    std::optional<BumpLayer> b = wall_bumps(c, p, wall, side, box);
    if (!b || b->count_x != w.at("bumps_per_row").get<std::size_t>() || b->rows != w.at("rows").get<std::size_t>())
        throw std::runtime_error(std::string(side) + ": the bumps laid out again differ from run.walls");
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4 || argc > 5 || (argc == 5 && std::string(argv[4]) != "trough")) {
        std::cerr << "usage: wall_layer_of <point folder> <cell length, m> <depth, m> [trough]\n";
        return 2;
    }
    try {
        const fs::path dir = argv[1];
        std::ifstream in(dir / "summary.json");
        if (!in) throw std::runtime_error((dir / "summary.json").string() + ": missing");
        const nlohmann::json summary = nlohmann::json::parse(in);
        const ParticleBox box{.length = std::stod(argv[2]), .gap = 0, .width = std::stod(argv[3]), .periodic_z = argc == 4};
        const auto bottom = bumps(summary, "bottom", box), top = bumps(summary, "top", box);
        const ParticleState st = read_particle_state(dir / kFinalStateFile);
        nlohmann::json j = wall_layer_record(st, box, summary.at("inputs").at("speed").get<double>(),
                                             bottom ? &*bottom : nullptr, top ? &*top : nullptr, false);
        const double U = summary.at("inputs").at("speed").get<double>();
        j["summary_slip_over_U"] = {{"bottom", summary.at("outputs").at("slip_bottom").at("value").get<double>() / U},
                                    {"top", summary.at("outputs").at("slip_top").at("value").get<double>() / U}};
        std::cout << j.dump(2) << '\n';
    } catch (const std::exception& e) {
        std::cerr << "wall_layer_of: " << e.what() << '\n';
        return 1;
    }
    return EXIT_SUCCESS;
}
