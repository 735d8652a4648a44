#include <unilateral/base/input_error.h>
#include <unilateral/lcp/io.h>
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
      check_parameter(!value.empty(), "LCP", name, "''",
                      "an LCP needs all three files");
  }

  lcp::Report
  LcpScene::run(RunContext &context)
  {
    lcp::Problem problem;
    {
      dealii::TimerOutput::Scope scope(*context.timer, "read LCP");
      problem = lcp::read_problem(
        resolve_relative_to(context.parameter_file, matrix_file),
        resolve_relative_to(context.parameter_file, rhs_file),
        resolve_relative_to(context.parameter_file, constraints_file));
    }
    export_lcp_if_requested(context, problem);

    lcp::Solution     solution;
    const lcp::Report report = solve(context, *this, problem, solution);

    {
      dealii::TimerOutput::Scope scope(*context.timer, "output");
      const std::string directory = context.output_directory.string();
      lcp::write_vector(solution.u, directory + "/u.txt");
      lcp::write_vector(solution.lambda, directory + "/lambda.txt");
      lcp::Vector active(solution.active_set.size());
      for (std::size_t k = 0; k < solution.active_set.size(); ++k)
        active[k] = solution.active_set[k] + 1;
      lcp::write_vector(active, directory + "/active_set.txt");
    }

    print_solver_summary(*context.out, problem, report);
    write_summary(context, summary_base(context, "lcp", problem, report));
    return report;
  }

  UNILATERAL_REGISTER_SCENE(LcpScene,
                            "lcp",
                            "an LCP read from Matrix Market and text files")
} // namespace unilateral
