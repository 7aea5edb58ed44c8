cmake_minimum_required(VERSION 3.16)
# Fails if a tracked file dates something by a work session (the word, then a number, as in
# "Sess[i]on 28", "sess[i]ons 27-28", "sess[i]on-3"): a reader outside the project's history cannot
# find one. Date a measurement and name the commit it was recorded in instead. The rule: session or
# sessions, any case, not inside a longer word or identifier, then a digit, directly or after one
# space, hyphen or en dash. Prose without a number ("one session", "six sessions", DBUS_SESSION_BUS)
# passes; a number wrapped onto the next line is not caught (git grep matches line by line). The
# brackets keep this file from matching itself.
set(pattern "(^|[^[:alnum:]_])[sS][eE][sS][sS][iI][oO][nN][sS]?([ -]?|–)[0-9]")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/TrackedFiles.cmake)
require_git_checkout()
forbid_tracked_text("${pattern}"
                    "tracked files date things by a session; write the date and the commit (git log -S'<the sentence>' finds it) instead"
                    "no tracked file dates anything by a session")
