#include "formats/pdf.h"

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/run/process.h"

namespace granlub::postproc {

std::optional<std::filesystem::path> pdf_converter() { return find_executable("rsvg-convert"); }

void write_pdf(const std::filesystem::path& converter, const std::filesystem::path& figure) {
    const auto svg = std::filesystem::absolute(figure);
    auto pdf = svg;
    pdf.replace_extension(".pdf");
    const auto partial = pdf.string() + ".partial", log = pdf.string() + ".log";
    const ProcessResult r =
        run_process({converter.string(), "--format=pdf", "--output=" + partial, svg.string()}, svg.parent_path(), log, 60);
    std::error_code ec;
    if (r.exit_code != 0 || !std::filesystem::exists(partial)) {
        const std::string tail = tail_lines(log, 5);
        std::filesystem::remove(partial, ec);
        std::filesystem::remove(log, ec);
        throw Error(fmt::format("{}: rsvg-convert could not make a PDF of it ({}): {}", figure.string(), r.describe(), tail));
    }
    std::filesystem::remove(log, ec);
    std::filesystem::rename(partial, pdf);
}

}  // namespace granlub::postproc
