// Each figure also as a PDF beside its SVG, for a paper in LaTeX: the report's own figure,
// converted by rsvg-convert (librsvg2-bin), so the PDF is the figure the report shows. Without
// rsvg-convert on PATH no PDF is written and the report says so where it lists its files.
#pragma once
#include <filesystem>
#include <optional>

namespace granlub::postproc {

// rsvg-convert's path, or nothing when it is not installed.
std::optional<std::filesystem::path> pdf_converter();

// plots/<stem>.svg -> plots/<stem>.pdf (written atomically). Throws Error naming the figure when
// the conversion fails.
void write_pdf(const std::filesystem::path& converter, const std::filesystem::path& svg);

}  // namespace granlub::postproc
