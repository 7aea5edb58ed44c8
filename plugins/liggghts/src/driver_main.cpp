// granlub-liggghts: LIGGGHTS 3.8 with granlub's contact models loaded. Same arguments as the
// `liggghts` executable (it is LIGGGHTS' own main plus the registration call), so it is a drop-in
// replacement, also under mpirun.
#include <mpi.h>

#include <cstdio>
#include <cstring>

#include "input.h"
#include "lammps.h"

#include "granlub_liggghts.h"

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    granlub_liggghts_register();  // explicit, so the linker can never drop the plugin
    // -h: the plugin's styles first; LIGGGHTS then prints its own and exits
    int me = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &me);
    for (int k = 1; k < argc && me == 0; k++)
        if (std::strcmp(argv[k], "-h") == 0 || std::strcmp(argv[k], "-help") == 0) {
            granlub_liggghts_print_styles(stdout);
            std::fflush(stdout);
            break;
        }
    LAMMPS_NS::LAMMPS* lammps = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    granlub_liggghts_register_styles(lammps);  // fix and compute styles live in the instance (register_fix_compute.cpp)
    lammps->input->file();
    delete lammps;
    MPI_Finalize();
    return 0;
}
