// Helpers shared by the masonry unit tests: run the scene from a parameter
// text without going through files, and print verdicts.
#pragma once

#include <unilateral/scenes/masonry/masonry_scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace masonry_test
{
  using namespace unilateral;
  using namespace unilateral::masonry;

  /// The scene and the solver parameters from a parameter file text.
  struct Setup
  {
    Parameters            parameters;
    lcp::SolverParameters solver;
  };

  inline Setup
  parse(const std::string &prm_text)
  {
    Setup                    setup;
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    setup.solver.declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    setup.parameters.parse_parameters(prm);
    setup.solver.parse_parameters(prm);
    return setup;
  }

  /// A scene that has run (solved, no VTU), with its report.
  template <int dim>
  struct RunOf
  {
    std::unique_ptr<MasonryScene<dim>> scene;
    lcp::Report                        report;
  };
  using Run = RunOf<2>;

  template <int dim = 2>
  inline RunOf<dim>
  run(const Setup &setup, const std::string &name)
  {
    static std::ostringstream quiet;
    RunOf<dim>                result;
    result.scene = std::make_unique<MasonryScene<dim>>(setup.parameters);
    dealii::TimerOutput timer(quiet,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    RunContext          context;
    context.run_name         = name;
    context.output_directory = std::filesystem::path("results") / name;
    std::filesystem::create_directories(context.output_directory);
    context.write_vtu = false;
    context.solver    = setup.solver;
    context.timer     = &timer;
    result.report     = result.scene->run(context);
    return result;
  }

  /// Only the setup (mesh, DOFs, contacts, change of variables).
  inline Sizes
  count(const Setup &setup)
  {
    MasonryScene<2> scene(setup.parameters);
    RunContext      context;
    scene.set_up(context);
    return scene.sizes();
  }

  /// Contacts with a force above 1e-10 of the largest (a closed contact
  /// without force may be in the active set or not).
  template <int dim>
  unsigned int
  carrying(const RunOf<dim> &run)
  {
    double largest = 0;
    for (const auto &c : run.scene->constraint_results())
      largest = std::max(largest, c.contact_force);
    unsigned int n = 0;
    for (const auto &c : run.scene->constraint_results())
      n += c.contact_force > 1e-10 * largest;
    return n;
  }

  inline const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "NO";
  }
} // namespace masonry_test
