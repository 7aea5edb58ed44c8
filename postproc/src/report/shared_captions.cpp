// Shared caption sentences said once per part (see shared_captions.h).
#include "report/shared_captions.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace granlub::postproc {
namespace {

constexpr std::size_t kMostRepeats = 2;  // a sentence in more captions than this is said once per part

std::string joined(const std::vector<std::string>& sentences) {
    std::string s;
    for (const auto& t : sentences) s += (s.empty() ? "" : " ") + t;
    return s;
}

// Where a part's note goes: before the first figures of blocks [from, to), or before the fold that
// holds them; `to` when the part has none.
std::size_t before_first_figures(const std::vector<Block>& blocks, std::size_t from, std::size_t to) {
    std::size_t fold = to;
    int depth = 0;
    for (std::size_t i = from; i < to; ++i) {
        const Block::Kind k = blocks[i].kind;
        if (k == Block::Kind::FoldBegin && depth++ == 0) fold = i;
        if (k == Block::Kind::FoldEnd) --depth;
        if (k == Block::Kind::Figures) return depth > 0 ? fold : i;
    }
    return to;
}

}  // namespace

std::vector<std::string> caption_sentences(const std::string& caption) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t at = caption.find(". "); at != std::string::npos; at = caption.find(". ", at + 1)) {
        const std::size_t next = at + 2;
        if (next >= caption.size()) break;
        const auto c = static_cast<unsigned char>(caption[next]);
        if (std::islower(c) || std::isdigit(c)) continue;
        out.push_back(caption.substr(start, at + 1 - start));
        start = next;
    }
    if (start < caption.size()) out.push_back(caption.substr(start));
    for (auto& s : out)
        while (!s.empty() && s.back() == ' ') s.pop_back();
    std::erase_if(out, [](const std::string& s) { return s.empty(); });
    return out;
}

void say_shared_captions_once(Report& rep) {
    std::map<std::string, std::size_t> count;
    for (const Block& b : rep.blocks)
        for (const FigureRef& f : b.figures)
            for (const auto& s : caption_sentences(f.caption)) ++count[s];
    const auto shared = [&](const std::string& s) { return count[s] > kMostRepeats; };
    // Part by part, from the last (inserting a block leaves the earlier parts' indices as they are).
    std::size_t end = rep.blocks.size();
    for (std::size_t i = rep.blocks.size(); i-- > 0;) {
        const Block& h = rep.blocks[i];
        if (i > 0 && !(h.kind == Block::Kind::Heading && h.level == 2)) continue;
        std::vector<std::string> said;
        for (std::size_t k = i; k < end; ++k)
            for (FigureRef& f : rep.blocks[k].figures) {
                std::vector<std::string> own;
                bool moved = false;
                for (auto& s : caption_sentences(f.caption)) {
                    if (!shared(s)) {
                        own.push_back(std::move(s));
                        continue;
                    }
                    moved = true;
                    if (std::find(said.begin(), said.end(), s) == said.end()) said.push_back(std::move(s));
                }
                if (moved) f.caption = joined(own);
            }
        if (!said.empty()) {
            Block note;
            note.kind = Block::Kind::Text;
            note.text = "Figures below: " + joined(said);
            rep.blocks.insert(rep.blocks.begin() + static_cast<std::ptrdiff_t>(before_first_figures(rep.blocks, i, end)),
                              std::move(note));
        }
        end = i;
    }
}

}  // namespace granlub::postproc
