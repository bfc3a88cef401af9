# One interface target carries the warning flags, so third-party headers are not affected.
add_library(animpak_warnings INTERFACE)
target_compile_options(animpak_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
