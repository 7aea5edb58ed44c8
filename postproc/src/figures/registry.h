// Every figure of the report, one row each: the function that builds it and the heading it stands
// under. compare draws each row's figures and writes their files (plots/); the report places them
// by heading. A new figure is its own source file plus one row in registry.cpp (postproc/README.md,
// "Adding a figure").
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "formats/figure_model.h"
#include "formats/report.h"
#include "results/collect.h"

namespace granlub::postproc {

// The headings the report places at fixed spots (report/report_builder.cpp).
inline constexpr const char* kProfilesHeading = "Profiles across the gap";
inline constexpr const char* kCrossSectionHeading = "Cross-sections of the trough";
inline constexpr const char* kStressHeading = "Wall stresses against speed";
inline constexpr const char* kSlipHeading = "Slip at the walls";  // against roughness or speed: the titles say which
inline constexpr const char* kSolidFractionHeading = "Mean solid fraction";

struct FigureInput {
    const Case& c;
    const Collection& col;
    std::size_t point = 0;        // per-point rows: the index into col.points
    std::filesystem::path plots;  // drawn rows write their own files here
};

struct FigureRow {
    const char* heading;  // the report part it stands under (a new heading gets its own part)
    bool per_point;       // drawn once per point with usable results (folded by point), else once per case
    // A line-and-point figure: compare renders the SVG and writes its data, gnuplot source and PDF.
    std::vector<Figure> (*model)(const FigureInput&) = nullptr;
    // A figure drawn straight to SVG (the cross-section heat maps): it writes its own files.
    std::vector<FigureRef> (*drawn)(const FigureInput&) = nullptr;
};

// The rows in report order.
const std::vector<FigureRow>& figure_registry();

// The headings the rows name, in report order, each once.
std::vector<std::string> figure_headings();

}  // namespace granlub::postproc
