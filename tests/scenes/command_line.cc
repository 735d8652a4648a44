// The command line as a new user meets it (issue 21): an empty parameter
// file runs the default scene, which is valid but surprising, so one line on
// stdout says so; a directory given as the parameter file is "not a file";
// extra arguments after --help or --print-parameters are refused with one
// line and exit code 1, while the plain forms still work; include lines
// that lead back to a file being read are refused with one line.
#include "../application_test_tools.h"

#include <filesystem>

using namespace application_test;

namespace
{
  std::size_t
  count_lines_with(const std::string &text, const std::string &fragment)
  {
    std::size_t count = 0;
    std::size_t start = 0;
    while (start < text.size())
      {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
          end = text.size();
        count +=
          text.substr(start, end - start).find(fragment) != std::string::npos;
        start = end + 1;
      }
    return count;
  }

  void
  expect_note(const std::string &what, const std::string &file_name)
  {
    const Result result = run({file_name});
    std::cout << what << ":\n  exit code 0: " << yes_no(result.code == 0)
              << "\n  error output empty: " << yes_no(result.err.empty())
              << "\n  one line on stdout says no parameter is set: "
              << yes_no(count_lines_with(result.out, "sets no parameter") == 1)
              << "\n  and names the file and the default scene: "
              << yes_no(count_lines_with(result.out, file_name) >= 1 &&
                        count_lines_with(result.out, "masonry") >= 1)
              << "\n";
  }

  void
  expect_success(const std::string &what, const Result &result)
  {
    std::cout << what << ": exit code 0: " << yes_no(result.code == 0)
              << ", error output empty: " << yes_no(result.err.empty())
              << ", output printed: " << yes_no(!result.out.empty()) << "\n";
  }
} // namespace

int
main()
{
  // The default wall (m = 20) takes a second. It writes into output/ of the
  // working directory, where the test harness keeps its file 'output': run
  // it in a directory of its own.
  std::filesystem::create_directories("default_run");
  std::filesystem::current_path("default_run");
  write("empty.prm", "");
  expect_note("an empty parameter file", "empty.prm");
  write("comments.prm", "# nothing set here\n\n   # indented comment\n");
  expect_note("a parameter file of comments only", "comments.prm");
  std::filesystem::current_path("..");
  {
    write("not_empty.prm",
          "# a comment\nset Scene = masonry\n"
          "subsection Output\n  set Directory = results\nend\n"
          "subsection Masonry\n  set Blocks per side = 2\nend\n");
    const Result result = run({"not_empty.prm"});
    std::cout << "a parameter file that sets something: no such note: "
              << yes_no(result.code == 0 &&
                        count_lines_with(result.out, "sets no parameter") == 0)
              << "\n";
  }

  std::filesystem::create_directories("a_directory.prm");
  expect_error("a directory as the parameter file",
               run({"a_directory.prm"}),
               {"a_directory.prm", "not a file"});
  expect_error("a missing parameter file",
               run({"missing.prm"}),
               {"missing.prm", "no such file"});

  expect_error("--help with an extra argument",
               run({"--help", "masonry.prm"}),
               {"masonry.prm", "--help"});
  expect_error("-h with an extra argument", run({"-h", "x"}), {"'x'", "-h"});
  expect_error("--print-parameters json with an extra argument",
               run({"--print-parameters", "json", "out.json"}),
               {"out.json", "--print-parameters"});
  expect_error("--print-parameters with an unknown format",
               run({"--print-parameters", "xml"}),
               {"xml", "prm or json"});
  expect_error("two parameter files", run({"a.prm", "b.prm"}), {"2"});

  // Before 1e62eb9 deal.II's parser recursed until the stack overflowed
  // (exit 139, nothing on stderr).
  write("includes_itself.prm",
        "set Scene = masonry\ninclude includes_itself.prm\n");
  expect_error("a parameter file that includes itself",
               run({"includes_itself.prm"}),
               {"includes_itself.prm", "include cycle"},
               false); // (the line quotes the folder the test runs in)
  write("cycle_a.prm", "set Scene = masonry\ninclude cycle_b.prm\n");
  write("cycle_b.prm", "# the second file\ninclude cycle_a.prm\n");
  expect_error("two parameter files that include each other",
               run({"cycle_a.prm"}),
               {"cycle_b.prm", "cycle_a.prm", "include cycle"},
               false);
  // An included file saved with a UTF-8 byte-order mark: deal.II's parser
  // refused its first line as unparsable, a line that looks well-formed.
  write("includes_marked.prm", "set Scene = masonry\ninclude marked.prm\n");
  write("marked.prm", "\xEF\xBB\xBFset Scene = masonry\n");
  expect_error("an included file with a byte-order mark",
               run({"includes_marked.prm"}),
               {"marked.prm", "byte-order mark", "without one"},
               false); // (the line quotes the folder the test runs in)

  expect_success("--help", run({"--help"}));
  expect_success("--print-parameters", run({"--print-parameters"}));
  expect_success("--print-parameters json",
                 run({"--print-parameters", "json"}));
}
