// [case] base (case_base.h): a case file merged over the case it is a variant of.
#include "case_base.h"

#include <algorithm>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/text.h"

namespace granlub {

namespace {

// `over`'s entries merged into `into`: a table into a table key by key, anything else replacing.
// Nodes are moved, never copied: toml++ keeps a node's source region (its file) only on a move.
void merge_over(toml::table& into, toml::table&& over) {
    for (auto&& [key, node] : over) {
        if (auto* t = node.as_table())
            if (auto* mine = into.get_as<toml::table>(key)) {
                merge_over(*mine, std::move(*t));
                continue;
            }
        into.insert_or_assign(key, std::move(node));
    }
}

// `chain`: the files read so far, as canonical paths, this one last.
toml::table with_bases(toml::table root, const std::string& source, std::vector<std::string>& chain,
                       std::vector<CaseFileText>& bases) {
    const auto* cs = root.get_as<toml::table>("case");
    const toml::node* node = cs ? cs->get("base") : nullptr;
    const auto* named = node ? node->as_string() : nullptr;  // not a string: [case]'s own check says so
    if (!named || named->get().empty()) return root;
    const auto fail = [&](const std::string& why) {
        throw CaseError(fmt::format("{}: [case] base = \"{}\": {}", where(source, node->source()),
                                    clipped(one_line(named->get())), why));
    };
    if (chain.size() > kMaxBaseChain)
        fail(fmt::format("a chain of more than {} bases ({} ...)", kMaxBaseChain, fmt::join(chain, " -> ")));
    CaseFileText base;
    try {
        base = read_case_file(std::filesystem::path(source).parent_path() / named->get());
    } catch (const CaseError& e) {
        fail(e.what());
    }
    std::error_code ec;
    // named as cases/twin/../parent/case.toml: shown as cases/parent/case.toml when that is the same file
    if (const auto plain = base.file.lexically_normal(); std::filesystem::equivalent(plain, base.file, ec))
        base.file = plain;
    const std::string id = std::filesystem::weakly_canonical(base.file, ec).string();
    if (std::find(chain.begin(), chain.end(), id) != chain.end())
        fail(fmt::format("a cycle: {} -> {}", fmt::join(chain, " -> "), id));
    chain.push_back(id);
    const std::string base_source = base.file.string();
    toml::table under = read_toml(base.text, base_source);
    bases.push_back(std::move(base));
    under = with_bases(std::move(under), base_source, chain, bases);
    under.erase("case");  // identity is never inherited
    merge_over(under, std::move(root));
    return under;
}

}  // namespace

CaseWithBases merge_bases(toml::table root, const std::string& source) {
    CaseWithBases out;
    std::error_code ec;
    std::vector<std::string> chain{std::filesystem::weakly_canonical(source, ec).string()};
    out.root = with_bases(std::move(root), source, chain, out.bases);
    return out;
}

}  // namespace granlub
