#include <unilateral/base/input_error.h>
#include <unilateral/lcp/io.h>
#include <unilateral/lcp/solve_lcp.h>
#include <unilateral/scenes/lcp_scene.h>

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <ostream>

namespace unilateral
{
  std::string
  resolve_relative_to(const std::string &parameter_file,
                      const std::string &file_name)
  {
    const std::filesystem::path path(file_name);
    if (path.is_absolute())
      return file_name;
    return (std::filesystem::path(parameter_file).parent_path() / path)
      .string();
  }

  void
  LcpScene::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("LCP");
    prm.declare_entry("Matrix file",
                      "",
                      dealii::Patterns::Anything(),
                      "A in Matrix Market coordinate format (real, general or "
                      "symmetric; 1-based). A relative path is taken from "
                      "the folder of the parameter file.");
    prm.declare_entry("Right-hand side file",
                      "",
                      dealii::Patterns::Anything(),
                      "b: one number per line. A relative path is taken "
                      "from the folder of the parameter file.");
    prm.declare_entry("Constraints file",
                      "",
                      dealii::Patterns::Anything(),
                      "S and its lower bounds: one line 'index lower_bound' "
                      "per constrained index (1-based). A relative path is "
                      "taken from the folder of the parameter file.");
    prm.leave_subsection();
  }

  LcpScene::LcpScene(dealii::ParameterHandler &prm)
    : Scene(registered_name)
  {
    prm.enter_subsection("LCP");
    matrix_file      = prm.get("Matrix file");
    rhs_file         = prm.get("Right-hand side file");
    constraints_file = prm.get("Constraints file");
    prm.leave_subsection();
    for (const auto &[name, value] :
         {std::pair{"Matrix file", matrix_file},
          std::pair{"Right-hand side file", rhs_file},
          std::pair{"Constraints file", constraints_file}})
      check_parameter(
        !value.empty(), "LCP", name, "''", "an LCP needs all three files");
  }

  void
  LcpScene::assemble_system(RunContext &context)
  {
    lcp_problem = lcp::read_problem(
      resolve_relative_to(context.parameter_file, matrix_file),
      resolve_relative_to(context.parameter_file, rhs_file),
      resolve_relative_to(context.parameter_file, constraints_file));
    // Verified here, where the error can name the file.
    try
      {
        lcp::verify_semidefinite(lcp_problem);
      }
    catch (const InputError &error)
      {
        throw InputError(matrix_file + ": " + error.what());
      }
    lcp_problem.known_semidefinite = true;
  }

  void
  LcpScene::postprocess(const RunContext &context, lcp::Report &)
  {
    if (!context.writes_files) // another rank writes them
      return;
    const std::string directory = context.output_directory.string();
    lcp::write_vector(lcp_solution.u, directory + "/u.txt");
    lcp::write_vector(lcp_solution.lambda, directory + "/lambda.txt");
    lcp::Vector active(lcp_solution.active_set.size());
    for (std::size_t k = 0; k < lcp_solution.active_set.size(); ++k)
      active[k] = lcp_solution.active_set[k] + 1;
    lcp::write_vector(active, directory + "/active_set.txt");
  }

  UNILATERAL_REGISTER_SCENE(LcpScene,
                            "an LCP read from Matrix Market and text files")
} // namespace unilateral
