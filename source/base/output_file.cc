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
    const std::string partial_suffix = ".partial";

    std::string
    partial_name(const std::string &name)
    {
      return name + partial_suffix;
    }
  } // namespace

  std::string
  name_when_written(const std::string &file_name)
  {
    const std::size_t n = partial_suffix.size();
    return file_name.size() > n &&
               file_name.compare(file_name.size() - n, n, partial_suffix) == 0 ?
             file_name.substr(0, file_name.size() - n) :
             file_name;
  }

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
