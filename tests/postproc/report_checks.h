// What a reader of a generated report must never meet, as checks the tests share: a figure title
// cut at its figure's edge, and a caption sentence said more than twice.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace granlub::test {

// The title lines of one SVG figure (the <text class="title"> svg_title.h writes) that would run
// past the figure's edge: each line's width by svg_title.h's estimate (DejaVu Sans Bold's advance
// widths, the estimate the layout wraps with) against the room around its centre in the figure's
// width. One message per such line, and one when the figure has no such title; empty when none.
std::vector<std::string> cut_title_lines(const std::string& svg);

// cut_title_lines over every .svg in `plots`, each message prefixed with the file's name.
std::vector<std::string> cut_titles(const std::filesystem::path& plots);

// The caption sentences (postproc's caption_sentences) of an HTML report's figures that appear in
// more than two captions, each with its count ("3x Log-log; ...").
std::vector<std::string> repeated_caption_sentences(const std::string& html);

}  // namespace granlub::test
