// The unilateral executable: everything lives in the core library.
#include <unilateral/application.h>

int
main(int argc, char **argv)
{
  return unilateral::run_application(argc, argv);
}
