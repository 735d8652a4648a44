// The unilateral command: a launcher that sets what glibc and OpenBLAS
// read only at start-up (start_up.h says why) and then becomes the program
// proper, unilateral-run, beside it. It loads none of deal.II's libraries,
// so that they are loaded once, by the program, with those settings.
#include <unilateral/base/start_up.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

int
main(int, char **argv)
{
  namespace start_up = unilateral::start_up;
  start_up::one_blas_thread_under_address_space_limit();
  // Under an MPI launcher every rank would fault in its huge pages on cores
  // the others use: left to the user there (mpirun -x GLIBC_TUNABLES=...).
  if (!start_up::launched_by_mpi())
    start_up::huge_pages();
  const std::string program =
    start_up::beside_this_executable("unilateral-run", argv[0]);
  if (!program.empty())
    execv(program.c_str(), argv);
  // An installation without the program beside the launcher (a copy of
  // the launcher alone): exit 1, as for other input the user can mend.
  std::cerr << "unilateral: error: cannot start the program '"
            << (program.empty() ? "unilateral-run" : program) << "': "
            << (program.empty() ? "the folder of this executable is unknown" :
                                  std::strerror(errno))
            << "; 'unilateral' is a launcher that starts 'unilateral-run' from "
               "its own folder: keep the two together (copy both, or link to "
               "the launcher with a symbolic link), or run unilateral-run "
               "directly"
            << std::endl;
  return 1;
}
