// Prints the particle tests' small shear cell (tests/liggghts/tiny_cell_text.h) as a case file, so
// that a shell test (slurm_one_node.sh) runs the same cell as the C++ tests instead of a copy of it.
// Usage: print_tiny_cell NAME OPERATING DEM [AFTER]: tiny_cell(NAME, OPERATING, DEM), then AFTER.
#include <cstdio>
#include <iostream>

#include "tiny_cell_text.h"

int main(int argc, char** argv) {
    if (argc != 4 && argc != 5) {
        std::fputs("usage: print_tiny_cell NAME OPERATING DEM [AFTER]\n", stderr);
        return 2;
    }
    std::cout << granlub::test::tiny_cell(argv[1], argv[2], argv[3]) << (argc == 5 ? argv[4] : "");
    return 0;
}
