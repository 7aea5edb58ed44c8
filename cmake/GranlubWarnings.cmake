# Warnings for granlub's own targets (not for third-party headers, which are SYSTEM includes).
add_library(granlub_warnings INTERFACE)
target_compile_options(granlub_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                       -Wno-sign-conversion)
