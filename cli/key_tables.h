// The case-key tables in the Markdown pages (module READMEs, docs/case-keys.md), kept equal to
// the declarations: a table stands between the marker lines
//
//   <!-- keys:SECTION -->
//   | key | default | allowed | unit | meaning |     (what key_table() prints for [SECTION])
//   <!-- /keys -->
//
// `granlub keys --update FILE...` rewrites what stands between the markers; `granlub keys --check
// FILE...` (the repo_key_tables test, on every tracked page) reports a table that differs and a
// key table written outside markers, so a page cannot drift from the schema unnoticed.
#pragma once
#include <string>
#include <vector>

#include "granlub/case/case.h"

namespace granlub::cli {

struct KeyTablePage {
    std::string text;                   // the page with every marked table as the declarations give it
    std::vector<std::string> stale;     // "FILE:LINE: ..." for each marked table that differs from them
    std::vector<std::string> problems;  // the same for what --update cannot mend: bad markers, unmarked tables
    int tables = 0;                     // marked tables found
};

// `text` is the page `file` (the name is only used in the messages).
KeyTablePage refresh_key_tables(const std::string& text, const std::string& file, const Schema& schema);

// `granlub keys --check` (update = false): prints every stale table and problem, returns 1 if any.
// `granlub keys --update`: rewrites the files whose tables are stale; returns 1 if problems remain.
int check_key_tables(const std::vector<std::string>& files, bool update, const Schema& schema);

}  // namespace granlub::cli
