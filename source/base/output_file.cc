#include <unilateral/base/input_error.h>
#include <unilateral/base/output_file.h>

namespace unilateral
{
  void
  close_written_file(std::ofstream &file, const std::string &name)
  {
    file.close();
    if (!file)
      throw InputError("cannot write '" + name +
                       "': the disk may be full, or the file not writable");
  }
} // namespace unilateral
