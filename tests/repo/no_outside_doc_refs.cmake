cmake_minimum_required(VERSION 3.16)
# Fails if a tracked file points at documents a clone of this repository does not have: the
# developers' notes kept next to the checkout (the pattern below) or their file names. The
# project's own pages live in docs/. The brackets keep this file from matching itself.
set(pattern "\\.\\./shar[e]d|shar[e]d/docs|/work/shar[e]d|ca-mod[e]l\\.md|continuum-th[e]ory|seeds-dig[e]st|liggghts-plug[i]n\\.md|dense-cont[a]cts|yad[e]\\.md")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/TrackedFiles.cmake)
require_git_checkout()
forbid_tracked_text("${pattern}"
                    "tracked files point outside the repository; cite the paper and equation, or a page under docs/, instead"
                    "no tracked file points outside the repository")
