#include <unilateral/base/input_error.h>
#include <unilateral/base/output_file.h>

#include <filesystem>

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

  namespace
  {
    std::string
    partial_name(const std::string &name)
    {
      return name + ".partial";
    }
  } // namespace

  std::ofstream
  open_for_writing(const std::string &name)
  {
    std::ofstream file(partial_name(name));
    if (!file)
      throw InputError("cannot write '" + name +
                       "': check that the directory exists and is writable");
    return file;
  }

  void
  finish_writing(std::ofstream &file, const std::string &name)
  {
    close_written_file(file, name);
    std::error_code error;
    std::filesystem::rename(partial_name(name), name, error);
    if (error)
      throw InputError("cannot write '" + name + "': " + error.message());
  }
} // namespace unilateral
